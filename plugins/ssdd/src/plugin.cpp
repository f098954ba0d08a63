#include "ssdd.h"

#include <darkroom/plugin.h>

namespace {

void registerTypes(darkroom::Registrar& r) {
    r.addFilter<darkroom::Ssdd>(
        "SSDD", "Shading",
        "Screen-space depth darkening (Luft et al. 2006, unsharp masking the depth buffer): the "
        "difference between a Gaussian-blurred depth and the depth darkens surfaces that lie "
        "behind nearby occluders. Adds the factor channel SSDD in [0, 1]; background is ignored "
        "by the blur and left at 1.");
}

}  // namespace

DARKROOM_PLUGIN("ssdd", "0.1.0", registerTypes)
