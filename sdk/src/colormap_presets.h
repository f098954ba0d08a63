#pragma once
// Built-in colour maps (internal to the SDK library).
#include <darkroom/colormap.h>

#include <cstddef>

namespace darkroom::detail {

struct PresetPoint {
    double x;
    float r, g, b;  // sRGB-encoded, as published
};

struct Preset {
    const char* name;  // canonical, as listed by colorMapPresets()
    const PresetPoint* points;
    std::size_t count;
    ColorMapSpace space;
    bool hasNanColor;
    float nan[3];  // sRGB-encoded
};

// All presets, in the order colorMapPresets() lists them.
const Preset* presets(std::size_t& count);

}  // namespace darkroom::detail
