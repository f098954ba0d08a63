#pragma once
#include <darkroom/export.h>
#include <darkroom/value.h>

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace darkroom {

struct ColorMapPoint {
    double x = 0;               // position, normalised to [0, 1] after loading
    float r = 0, g = 0, b = 0;  // linear RGB
};

// How colours between two control points are blended; the names are
// ParaView's "ColorSpace" values.
enum class ColorMapSpace : std::uint8_t {
    // Straight lines between the sRGB-encoded colours, as ParaView and
    // matplotlib do (a two-point grey ramp is perceptually even).
    RGB,
    // Straight lines in CIELAB (D65).
    Lab,
    // Moreland's diverging path in Msh space: two saturated colours of
    // different hue pass through a neutral white in between.
    Diverging,
    // Straight lines in HSV of the sRGB-encoded colours, hue not wrapped
    // (ParaView's default HSVWrap = off).
    HSV,
};

DARKROOM_API const char* toString(ColorMapSpace s);

// A resolved colour map: control points plus the colour for NaN.
struct ColorMapData {
    std::string name;
    std::vector<ColorMapPoint> points;  // sorted by x, first at 0, last at 1, at least two
    ColorMapSpace space = ColorMapSpace::RGB;
    Color nanColor{1.0f, 1.0f, 0.0f, 1.0f};  // linear; ParaView's default yellow
    bool hasNanColor = false;                // true when the source defined one

    // Linear colour at t in [0, 1] (clamped), alpha 1. NaN t gives nanColor.
    DARKROOM_API Color sample(double t) const;
    // n >= 2 samples at t = i / (n - 1): a lookup table for per-pixel work,
    // exact at both ends.
    DARKROOM_API std::vector<Color> table(int n) const;
};

// Names of the built-in presets: viridis, plasma, inferno, magma, turbo (from
// matplotlib), cool-to-warm, blackbody, grayscale, jet, rainbow.
DARKROOM_API std::vector<std::string> colorMapPresets();

// True when `name` names a preset. Matching ignores case, spaces, '-' and '_'
// and a trailing " (matplotlib)", so ParaView's names ("Cool to Warm",
// "Black-Body Radiation", "Viridis (matplotlib)") are accepted too.
DARKROOM_API bool isColorMapPreset(std::string_view name);

// `spec` is a preset name or the path of a ParaView colour-map JSON file
// (already resolved by the caller): an array of objects with "Name",
// "RGBPoints" [x, r, g, b, ...] (sRGB-encoded, x in any range: normalised to
// [0, 1]), optional "NanColor" [r, g, b(, a)] and "ColorSpace"; or one such
// object. The first entry with RGBPoints is used. Throws darkroom::Error
// naming the file and what is wrong.
DARKROOM_API ColorMapData loadColorMap(std::string_view spec);

}  // namespace darkroom
