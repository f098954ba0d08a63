#pragma once
// Where the outlines go: pixels within `width` of a depth or object-id
// discontinuity, on one chosen side of it.
#include <darkroom/context.h>

#include <cstdint>
#include <vector>

namespace darkroom::passes {

struct SilhouetteOptions {
    double width = 1.0;            // disk radius in pixels; 1 = the 4-neighbours
    double depthThreshold = 0.05;  // relative depth jump |Zq - Zp| / Zp (nearer pixel's depth)
    bool nearSide = true;          // draw on the nearer (true) or farther pixel of a jump
};

// 1 where a pixel is on the chosen side of a discontinuity with some pixel q
// within `width`, else 0. A depth discontinuity: q is background (+inf) or its
// depth differs by more than depthThreshold relative to the nearer depth. An
// id discontinuity (ids may be null): different ids; the nearer pixel of the
// two is the near side, equal depths go to the lower id. NaN and -inf depths
// are "no data": never an edge, never next to one.
std::vector<float> silhouette(Context& ctx, const float* depth, const std::uint32_t* ids,
                              int width, int height, const SilhouetteOptions& options);

}  // namespace darkroom::passes
