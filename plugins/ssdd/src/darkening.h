#pragma once
// The SSDD factor of every pixel: the depth blurred by a box cascade
// (box_cascade.h) as a normalised convolution — pixels without a surface have
// weight 0, so background never contributes and pixels near it or near the
// image border average only the surface they can see — compared with the
// depth itself.
#include "box_cascade.h"

#include <darkroom/context.h>

namespace darkroom::passes {

struct DarkeningJob {
    const float* depth = nullptr;
    int width = 0, height = 0;
    BoxCascade horizontal, vertical;
    double strength = 0.5;
    double footprint = 0.0;  // world size of sigma at unit depth (perspective) or anywhere (orthographic)
    bool perspective = true;
    float* factor = nullptr;  // out: exp(-strength max(0, -dD) / (footprint [* Z])); 1 without a surface
};

void depthDarkening(Context& ctx, const DarkeningJob& job);

// The kernels of depthDarkening (darkening_simd.cpp), exposed for its driver.
// Depths are blurred relative to `reference` (the nearest surface), which keeps
// the sums accurate for scenes far from the camera.
constexpr int kStripColumns = 32;  // columns blurred together along y
constexpr int kBlockRows = 16;     // rows blurred together along x
struct BlurPlanes {
    float* depth;  // sum of weight * (Z - reference) over surface pixels
    float* mask;   // sum of weight over surface pixels
};
// Rows [y0, y0 + kBlockRows) (fewer at the bottom): masked depth along x into
// `planes`. The rows are transposed into a block (x major), so the boxes run
// as running sums, one lane per row, like the columns: the cost does not
// depend on sigma. `scratch` holds rowScratch(job) floats.
void blurRows(const DarkeningJob& job, float reference, int y0, const BlurPlanes& planes, float* scratch);
// Columns [x0, x0 + kStripColumns) (fewer at the right): `planes` along y,
// then the factor. A whole strip reads the planes and the depth and writes the
// factor in place; only a narrower strip at the right is copied.
// `scratch` holds columnScratch(job) floats.
void blurColumnsAndDarken(const DarkeningJob& job, float reference, int x0, const BlurPlanes& planes, float* scratch);
// What blurRows and blurColumnsAndDarken need of scratch, in floats.
std::size_t rowScratch(const DarkeningJob& job);
std::size_t columnScratch(const DarkeningJob& job);
// The nearest surface depth of [begin, end), +inf when there is none.
float nearestDepth(const float* depth, std::size_t begin, std::size_t end);

}  // namespace darkroom::passes
