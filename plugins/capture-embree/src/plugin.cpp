// Entry point of the capture-embree plugin: registers the "embree" backend.
#include "embree_backend.h"

#include <darkroom/plugin.h>

namespace {

void registerTypes(darkroom::Registrar& r) {
    r.addCaptureBackend(darkroom::CaptureBackendInfo{
        "embree",
        "Ray traces G-buffers on the CPU with Embree 3: triangles, round tubes for lines and spheres for "
        "points, natively and without copying the geometry; coherent 8-ray packets over 16x16 tiles; "
        "identical output for any thread count.",
        [] { return darkroom::embree::createBackend(); }});
}

}  // namespace

DARKROOM_PLUGIN("capture-embree", "0.1.0", registerTypes)
