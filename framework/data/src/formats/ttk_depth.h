#pragma once
// TTK's normalised depth back to planar world depth (vti.h, ttkDepthToPlanar,
// says what and why), inline: the .vti reader and the HDF5 module (pycinema
// keeps depth the same way) both convert with it, and the module, opened
// by the data library, does not link the data library.
#include <cmath>
#include <limits>

namespace darkroom::formats {

inline float planarFromTtkDepth(float d, double nearPlane, double farPlane) {
    if (std::isnan(d)) return std::numeric_limits<float>::infinity();
    if (nearPlane == 0.0 && farPlane == 0.0) return d;
    if (d >= 1.f) return std::numeric_limits<float>::infinity();
    return float(nearPlane + double(d) * (farPlane - nearPlane));
}

}  // namespace darkroom::formats
