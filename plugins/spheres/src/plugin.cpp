#include "spheres.h"

#include <darkroom/plugin.h>

namespace {

void registerTypes(darkroom::Registrar& r) {
    r.addFilter<darkroom::Spheres>(
        "Spheres", "Geometry",
        "Draws a list of points (CSV x, y, z with optional radius and field columns, or the vertices of a VTK, "
        "PLY or OBJ file) as exactly ray-cast spheres into a G-buffer (Z, N, fields) with the camera and size of "
        "another image, to composite with it; the list may be the one a capture stored beside each entry.");
}

}  // namespace

DARKROOM_PLUGIN("spheres", "0.1.0", registerTypes)
