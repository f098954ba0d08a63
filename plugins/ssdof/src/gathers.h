#pragma once
// The two gathers. Each writes, for every pixel, the composited premultiplied
// colour into `result` and sets `unchanged` where the pixel is in focus with no
// near-field light on it (the caller then copies the input bit for bit).
#include "layers.h"

#include <cstdint>

namespace darkroom {
class Context;
}

namespace darkroom::ssdof {

struct GatherResult {
    std::vector<Rgba> colour;
    std::vector<std::uint8_t> unchanged;
};

// Disc aperture: `samples` points of a Vogel (golden-angle) spiral scaled to
// the CoC, plus the pixel itself.
void gatherDisc(const WorkImage& w, int samples, Context& ctx, GatherResult& out);

// Hexagonal aperture (circumradius = CoC radius, a corner pointing `rotation`
// degrees clockwise from up) as three rhombi, each two skewed 1D box blurs,
// evaluated in two passes (McIntosh, Riecke & DiPaola 2012).
void gatherHexagon(const WorkImage& w, double rotationDegrees, Context& ctx, GatherResult& out);

}  // namespace darkroom::ssdof
