#include "normals.h"

#include <darkroom/plugin.h>

namespace {

void registerTypes(darkroom::Registrar& r) {
    r.addFilter<darkroom::Normals>(
        "Normals", "Geometry",
        "Reconstructs world-space normals (N.*), view-space normals (Nv.*) and world positions "
        "(P.*) from planar depth Z and the image's camera, discontinuity-aware by default. All "
        "input channels pass through; background (Z = +inf) gets NaN.");
}

}  // namespace

DARKROOM_PLUGIN("normals", "0.1.0", registerTypes)
