#include "color_mapping.h"

#include <darkroom/plugin.h>

namespace {

void registerTypes(darkroom::Registrar& r) {
    r.addFilter<darkroom::ColorMapping>(
        "ColorMapping", "Color",
        "Maps one scalar channel to linear RGBA through a colour map: a preset (viridis, plasma, "
        "inferno, magma, turbo, cool-to-warm, blackbody, grayscale, jet, rainbow) or a ParaView "
        "colour-map JSON file. The range is the finite minimum and maximum of the channel or set "
        "by hand; NaN gets its own colour; depth Z passes through and background (Z = +inf) "
        "becomes transparent.");
}

}  // namespace

DARKROOM_PLUGIN("colormapping", "0.1.0", registerTypes)
