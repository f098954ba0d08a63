#include "camera_node.h"

#include <darkroom/plugin.h>

namespace {

void registerTypes(darkroom::Registrar& r) {
    r.addFilter<darkroom::CameraNode>(
        "Camera", "Camera",
        "Sets or replaces the camera of an image from ParaView's values (position, focal point, view up, view "
        "angle or parallel scale), so SSAO, Normals, SSDoF and IBS can shade databases whose writer stored no "
        "camera (TTK, Ascent, ParaView). Optionally turns TTK's depth normalised between near and far back into "
        "planar distances.");
}

}  // namespace

DARKROOM_PLUGIN("camera", "0.1.0", registerTypes)
