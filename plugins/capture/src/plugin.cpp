// Entry point of the capture plugin: registers the `Capture` node.
#include "capture.h"

#include <darkroom/plugin.h>

namespace {

void registerTypes(darkroom::Registrar& r) {
    r.addFilter<darkroom::Capture>(
        "Capture", "Input/Output",
        "Renders G-buffers (depth, scalars, normals, ids) of a scene file for one of its cameras through a "
        "capture backend (default embree). The scene and its acceleration structure are cached while only the "
        "camera or resolution changes.");
}

}  // namespace

DARKROOM_PLUGIN("capture", "0.1.0", registerTypes)
