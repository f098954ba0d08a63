#pragma once
// ParaView's camera description (position, focal point, view up, view angle
// or parallel scale) as Darkroom's Camera, checked.
#include <darkroom/camera.h>

#include <string>

namespace darkroom {

struct ParaViewCamera {
    Vec3 position{0, 0, 1};
    Vec3 focalPoint{0, 0, 0};
    Vec3 viewUp{0, 1, 0};
    bool parallelProjection = false;
    double viewAngle = 30;     // degrees, vertical (vtkCamera::ViewAngle)
    double parallelScale = 1;  // half the view height in world units (vtkCamera::ParallelScale)
};

// The Camera for an image of width x height. Throws darkroom::Error (the host
// names the node) when the position equals the focal point, the view up is
// parallel to the view direction, or the angle or scale is out of range.
Camera cameraFromParaView(const ParaViewCamera& v, int width, int height);

}  // namespace darkroom
