#pragma once
// The parts of FXAA that run a vector of pixels at a time: the luma, the
// contrast check that leaves most pixels untouched, and the decision for the
// pixels that remain. All give the bits of the per-pixel code (luma.cpp,
// fxaa_kernel.cpp).
#include "fxaa_kernel.h"

#include <cstddef>
#include <cstdint>

namespace darkroom::fxaa {

// computeLuma (luma.h) for [begin, end); returns end, or begin when the span
// is shorter than a vector (the caller finishes it with computeLuma).
std::size_t lumaSpan(const float* r, const float* g, const float* b, const float* alpha, float* luma,
                     std::size_t begin, std::size_t end);

// For pixels [x0, x1) of row y, 1 <= x0, x1 <= width - 1, 1 <= y < height - 1:
// copies the colour of every pixel whose luma is NaN or whose contrast is
// below the thresholds (decide() would return no blend), and appends the x of
// every other pixel, in increasing order, to edgeXs[edgeCount...] (room for
// x1 - x0 + 64 entries needed: a vector store may write past the last one).
// Returns x1, or x0 when the span is shorter than a vector.
struct ColourRows {
    const float* in[4];  // R, G, B, A (A may be null)
    float* out[4];
};
int flatSpan(const LumaPlane& plane, const Settings& s, const ColourRows& colour, int y, int x0, int x1,
             std::int32_t* edgeXs, std::size_t& edgeCount);

// decide() for the `count` pixels (xs[k], ys[k]), whose luma must not be NaN,
// a vector of pixels at a time (the end-of-edge searches of all lanes run
// together, until the last lane has found both ends). Writes amount[k], the
// weight of the neighbour (0: keep the pixel), and partner[k], that
// neighbour's index clamped to the image (the pixel's own index when there is
// none). Edge pixels sit far apart in the image, so they come as a list rather
// than as spans of a row. Needs width * height <= INT32_MAX (int32 indices).
void decideList(const LumaPlane& plane, const Settings& s, const std::int32_t* xs, const std::int32_t* ys,
                std::size_t count, float* amount, std::int32_t* partner);

}  // namespace darkroom::fxaa
