#include "ssdof.h"

#include <darkroom/plugin.h>

namespace {

void registerTypes(darkroom::Registrar& r) {
    r.addFilter<darkroom::Ssdof>(
        "SSDoF", "Camera",
        "Screen-space depth of field: a thin-lens circle of confusion from planar depth, focal "
        "distance and lens diameter (in camera terms), gathered with a round (golden-angle "
        "spiral) or hexagonal (separable skewed box blurs) aperture. Near out-of-focus objects "
        "bleed over sharp background, far ones never over nearer sharp pixels; in-focus pixels "
        "stay bit-identical.");
}

}  // namespace

DARKROOM_PLUGIN("ssdof", "0.1.0", registerTypes)
