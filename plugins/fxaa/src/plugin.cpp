#include "fxaa.h"

#include <darkroom/plugin.h>

namespace {

void registerTypes(darkroom::Registrar& r) {
    r.addFilter<darkroom::Fxaa>(
        "FXAA", "Image",
        "Fast approximate anti-aliasing (FXAA 3.11 quality, Lottes 2011): detects aliased edges "
        "from the perceptual luma of the linear colour and blends each edge pixel with one "
        "neighbour across the edge, by how far it lies from the end of the staircase step, plus "
        "a sub-pixel term. NaN colour and transparent pixels are never blended into others; "
        "channels other than R, G, B, A pass through.");
}

}  // namespace

DARKROOM_PLUGIN("fxaa", "0.1.0", registerTypes)
