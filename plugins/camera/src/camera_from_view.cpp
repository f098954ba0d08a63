#include "camera_from_view.h"

#include <darkroom/error.h>

#include <cmath>
#include <string>

namespace darkroom {

Camera cameraFromParaView(const ParaViewCamera& v, int width, int height) {
    const Vec3 direction = v.focalPoint - v.position;
    const double distance = length(direction);
    if (!(distance > 0) || !std::isfinite(distance))
        throw Error("position and focalPoint must be distinct finite points (the view direction runs "
                          "from the position to the focal point)");
    const Vec3 forward = direction * (1.0 / distance);
    const double upLength = length(v.viewUp);
    if (!(upLength > 0) || length(cross(forward, v.viewUp * (1.0 / upLength))) < 1e-6)
        throw Error("viewUp must be a non-zero vector not parallel to the view direction (focalPoint - "
                          "position)");
    Camera c;
    c.position = v.position;
    c.forward = forward;
    c.up = v.viewUp * (1.0 / upLength);
    c.width = width;
    c.height = height;
    if (v.parallelProjection) {
        if (!(v.parallelScale > 0) || !std::isfinite(v.parallelScale))
            throw Error("parallelScale must be positive (half the view height in world units)");
        c.projection = Camera::Projection::Orthographic;
        c.viewHeight = 2.0 * v.parallelScale;
    } else {
        if (!(v.viewAngle > 0 && v.viewAngle < 180))
            throw Error("viewAngle must lie strictly between 0 and 180 degrees (vertical field of view)");
        c.projection = Camera::Projection::Perspective;
        c.fovYDegrees = v.viewAngle;
    }
    return c;
}

}  // namespace darkroom
