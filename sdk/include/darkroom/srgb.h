#pragma once
// The sRGB transfer curve (IEC 61966-2-1). Colour inside the graph is linear;
// 8-bit files and published colour tables are sRGB-encoded.
#include <cmath>

namespace darkroom {

// Encoded value in [0, 1] -> linear light.
inline float srgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

// Linear light -> encoded value; not clamped (callers clamp where they quantise).
inline float linearToSrgb(float c) {
    return c <= 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

}  // namespace darkroom
