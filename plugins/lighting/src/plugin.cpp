#include "lighting.h"

#include <darkroom/plugin.h>

namespace {

void registerTypes(darkroom::Registrar& r) {
    r.addFilter<darkroom::Lighting>(
        "Lighting", "Shading",
        "Lambert diffuse plus Blinn-Phong specular lighting of the colour (as albedo) from captured normals or "
        "normals reconstructed from depth: a headlight or one to four directional lights in view or world space, "
        "an ambient term that an optional AO input multiplies. Background is left alone.");
}

}  // namespace

DARKROOM_PLUGIN("lighting", "0.1.0", registerTypes)
