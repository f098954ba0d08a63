#pragma once
// Depth and normal pyramids for the multi-scale estimators: LineAO and
// PointAO read level l of a mean pyramid (the Gaussian pyramid of the
// papers, as mip-mapping builds it), SAO reads the level a tap's distance
// asks for from a rotated-grid subsample chain (McGuire et al. 2012), whose
// texels are real depths, never averages across a silhouette.
#include "frame.h"

#include <darkroom/context.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace darkroom::ssao {

// One level: unpadded rows; z = +inf where there is no surface; n the unit
// view-space normal (0 where there is no surface).
struct PyramidLevel {
    int width = 0, height = 0;
    std::vector<float> z, n[3];
    // RotatedGrid: the full-resolution pixel (y * width0 + x) each texel was
    // taken from, so a tap reconstructs its position where the depth lies.
    std::vector<std::uint32_t> source;
    std::size_t at(int x, int y) const { return std::size_t(y) * std::size_t(width) + std::size_t(x); }
};

enum class Reduction {
    RotatedGrid,  // texel (x, y) of level m+1 = texel (2x + (y&1 ^ 1), 2y + (x&1 ^ 1)) of level m
    Mean,         // mean depth and normal of the surface pixels of the 2 x 2 block
};

struct Pyramid {
    std::vector<PyramidLevel> levels;  // levels[0] = the frame at full resolution
};

// Levels 0 .. maxLevel (fewer when the image gets down to one pixel).
Pyramid buildPyramid(const Frame& g, Reduction reduction, int maxLevel, Context& ctx);

}  // namespace darkroom::ssao
