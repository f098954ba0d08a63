#include "point_list_ao.h"

#include <darkroom/plugin.h>

namespace {

void registerTypes(darkroom::Registrar& r) {
    r.addFilter<darkroom::PointListAo>(
        "PointListAO", "Shading",
        "Ambient occlusion cast by the spheres and round lines of a point list (e.g. the particles or "
        "streamlines a capture stored beside each entry) onto a G-buffer, in closed form per primitive: right "
        "where screen-space AO fails, on particles and lines a few pixels wide or less.");
}

}  // namespace

DARKROOM_PLUGIN("point-list-ao", "0.1.0", registerTypes)
