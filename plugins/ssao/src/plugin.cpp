#include "ssao.h"

#include <darkroom/plugin.h>

namespace {

void registerTypes(darkroom::Registrar& r) {
    r.addFilter<darkroom::Ssao>(
        "SSAO", "Shading",
        "Screen-space ambient occlusion from depth Z and the camera: a classic normal-oriented "
        "hemisphere estimator or a GTAO-style horizon estimator of cosine-weighted AO, for surfaces "
        "or for point/line geometry (thickness heuristic), followed by a depth-aware blur. Adds "
        "channel AO in [0, 1] (1 = unoccluded, background = 1); all input channels pass through.");
}

}  // namespace

DARKROOM_PLUGIN("ssao", "0.1.0", registerTypes)
