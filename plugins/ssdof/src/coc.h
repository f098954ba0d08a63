#pragma once
// Thin-lens circle of confusion in pixels, from planar depth and the camera
// that travels with the buffer.
#include <darkroom/camera.h>

namespace darkroom::ssdof {

struct LensModel {
    double aperture = 0.0;       // lens diameter, world units
    double focalDistance = 0.0;  // planar depth in focus, world units; +inf allowed
    double maxBlur = 16.0;       // clamp of the CoC radius, pixels
    // World size of one pixel per unit depth (perspective) or of one pixel
    // (orthographic), from the camera's field of view and image height.
    double pixelPerDepth = 0.0;
    bool orthographic = false;

    // Signed CoC radius in pixels: negative in front of the focal plane (near
    // field), positive behind it (far field), clamped to +-maxBlur. Depths that
    // are not finite and positive (+inf background, NaN = no data, -inf, <= 0)
    // are treated as background at infinity, whose CoC is finite.
    float signedRadius(float z) const;
};

// The lens for `camera` (width/height of the image override the camera's,
// which may be unset). Throws darkroom::Error on a camera without height.
LensModel makeLens(const Camera& camera, int imageHeight, double aperture, double focalDistance,
                   double maxBlur);

// Auto-focus: the median of the finite positive depths in the 5x5 window at the
// image centre, or +inf when there is none (focus at infinity).
double autoFocusDistance(const float* z, int width, int height);

}  // namespace darkroom::ssdof
