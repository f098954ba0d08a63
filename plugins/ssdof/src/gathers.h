#pragma once
// The two gathers. Each composites the two layers of every pixel and writes
// it to `out` (straight alpha), or copies the input where a pixel is in focus
// with no near-field light on it. A vector of pixels of a row at a time with
// the best SIMD instructions of the CPU, every sample's sums in the same
// order whatever the vector width, so the result does not depend on the
// instruction set.
#include "layers.h"

namespace darkroom::ssdof {

struct SpiralPoint {
    float x, y;  // unit-disc position of a point of the disc gather's spiral
};

// Disc aperture: `samples` points of a Vogel (golden-angle) spiral scaled to
// the CoC, plus the pixel itself.
void gatherDisc(const WorkImage& w, int samples, Context& ctx, const Output& out);

// Hexagonal aperture (circumradius = CoC radius, a corner pointing `rotation`
// degrees clockwise from up) as three rhombi, each two skewed 1D box blurs,
// evaluated in two passes (McIntosh, Riecke & DiPaola 2012).
void gatherHexagon(const WorkImage& w, double rotationDegrees, Context& ctx, const Output& out);

}  // namespace darkroom::ssdof
