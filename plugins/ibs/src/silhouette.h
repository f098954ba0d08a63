#pragma once
// Where the outlines go: pixels within `width` of a depth or object-id
// discontinuity, on one chosen side of it.
#include <darkroom/context.h>

#include <cstdint>
#include <utility>
#include <vector>

namespace darkroom::passes {

struct SilhouetteOptions {
    double width = 1.0;            // disk radius in pixels; 1 = the 4-neighbours
    double depthThreshold = 0.05;  // relative depth jump |Zq - Zp| / Zp (nearer pixel's depth)
    bool nearSide = true;          // draw on the nearer (true) or farther pixel of a jump
};

// Writes into `out` (width * height values) 1 where a pixel is on the chosen
// side of a discontinuity with some pixel q within `width`, else 0. A depth
// discontinuity: q is background (+inf) or its depth differs by more than
// depthThreshold relative to the nearer depth. An id discontinuity (ids may
// be null): different ids; the nearer pixel of the two is the near side,
// equal depths go to the lower id. NaN and -inf depths are "no data": never
// an edge, never next to one.
void silhouette(Context& ctx, const float* depth, const std::uint32_t* ids, int width, int height,
                const SilhouetteOptions& options, float* out);

// What one row of the search needs (silhouette.cpp, silhouette_simd.cpp).
struct SilhouetteJob {
    const float* depth;
    const std::uint32_t* ids;  // nullptr: depth edges only
    int width, height;
    std::vector<std::pair<int, int>> disk;  // offsets within the width, nearest first
    int radius;                             // largest |dx| in the disk
    double threshold;
    bool nearSide;
    float* out;
};

// Pixel (x, y), anywhere in the image.
void silhouetteAt(const SilhouetteJob& job, int x, int y);
// Pixels [x0, x1) of row y with radius <= x0 <= x1 <= width - radius, with
// the best SIMD instructions of the CPU; returns x1, or x0 when the span is
// shorter than a vector (then silhouetteAt does it).
int silhouetteSpan(const SilhouetteJob& job, int y, int x0, int x1);

}  // namespace darkroom::passes
