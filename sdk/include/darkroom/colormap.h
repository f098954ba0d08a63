#pragma once
#include <darkroom/export.h>
#include <darkroom/value.h>

#include <string>
#include <string_view>
#include <vector>

namespace darkroom {

struct ColorMapPoint {
    double x = 0;  // position, normalised to [0, 1] after loading
    float r = 0, g = 0, b = 0;  // linear RGB
};

// A resolved colour map: control points interpolated linearly (in linear RGB,
// or along the Moreland diverging path when `diverging`), plus the NaN colour.
struct ColorMapData {
    std::string name;
    std::vector<ColorMapPoint> points;  // sorted by x, at least two
    bool diverging = false;
    Color nanColor{1.0f, 1.0f, 0.0f, 1.0f};
    bool hasNanColor = false;  // true when the source defined one

    // Colour at t in [0, 1] (clamped). NaN t gives nanColor.
    DARKROOM_API Color sample(double t) const;
};

// Names of the built-in presets (viridis, plasma, inferno, magma, cool-to-warm,
// blackbody, grayscale, ...).
DARKROOM_API std::vector<std::string> colorMapPresets();

// `spec` is a preset name or the path of a ParaView colour-map JSON file
// (already resolved by the caller). Throws darkroom::Error naming the file and
// what is wrong.
DARKROOM_API ColorMapData loadColorMap(std::string_view spec);

}  // namespace darkroom
