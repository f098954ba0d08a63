#pragma once
// Half-resolution SSAO: the estimator at the pixels with even x and y, the
// others filled from their computed neighbours on the same surface
// (half_resolution.cpp).
#include "frame.h"

#include <cstdint>

namespace darkroom::ssao {

// Row y of `out` (a plane of the frame's layout): pixels with even x and y,
// and background, copied from `sparse` (1 on background); every other pixel
// the mean of its computed neighbours (left and right, above and below, or
// the four diagonal ones) when all lie within one pixel footprint of its
// tangent plane with normals within about 25 degrees. The others are listed
// in `missing` (room for the row's width) and counted in the return value;
// the caller computes them.
int fillRow(const Frame& g, int y, const float* sparse, float* out, std::int32_t* missing);

}  // namespace darkroom::ssao
