#include "eye_dome_lighting.h"

#include <darkroom/plugin.h>

namespace {

void registerTypes(darkroom::Registrar& r) {
    r.addFilter<darkroom::EyeDomeLighting>(
        "EyeDomeLighting", "Shading",
        "Eye-dome lighting (Boucheny et al. 2009; VTK's vtkEDLShading, ParaView, Potree): each pixel is darkened "
        "by the neighbours in front of it, measured in log2 depth on a ring of 8 pixels at several scales. Needs "
        "depth only (no normals, no camera): suited to point clouds and lines. Adds EDL and shades R, G, B.");
}

}  // namespace

DARKROOM_PLUGIN("eye-dome-lighting", "0.1.0", registerTypes)
