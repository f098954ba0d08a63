#pragma once
#include <darkroom/math.h>

#include <numbers>
#include <string>

namespace darkroom {

// A camera travels with every buffer it produced, so any pass can turn a pixel
// and its depth back into a world position. Pixel (0,0) is the top-left corner;
// pixel centres are at half-integers.
struct Camera {
    enum class Projection { Perspective, Orthographic };

    Vec3 position{0, 0, 1};
    Vec3 forward{0, 0, -1};  // unit view direction
    Vec3 up{0, 1, 0};        // need not be orthogonal to forward; orthonormalised on use
    Projection projection = Projection::Perspective;
    double fovYDegrees = 30.0;  // perspective: full vertical field of view
    double viewHeight = 2.0;    // orthographic: world-space height of the view
    int width = 0;
    int height = 0;

    bool operator==(const Camera&) const = default;

    // Orthonormal basis: right, true up, forward.
    void basis(Vec3& right, Vec3& trueUp, Vec3& fwd) const {
        fwd = normalize(forward);
        right = normalize(cross(fwd, up));
        trueUp = cross(right, fwd);
    }

    // Half-extent of the image plane at unit distance (perspective) or in world
    // units (orthographic), vertically.
    double halfHeight() const {
        return projection == Projection::Perspective
                   ? std::tan(fovYDegrees * std::numbers::pi / 360.0)
                   : viewHeight * 0.5;
    }

    // Image-plane offsets (right, up) of a continuous pixel coordinate.
    void planeOffsets(double px, double py, double& sx, double& sy) const {
        const double hh = halfHeight();
        const double hw = hh * (height > 0 ? double(width) / double(height) : 1.0);
        sx = (2.0 * px / width - 1.0) * hw;
        sy = (1.0 - 2.0 * py / height) * hh;
    }

    // Ray through continuous pixel coordinate (px, py). For perspective
    // cameras the direction is NOT normalised: its forward component is 1, so
    // the ray parameter t equals planar depth. Orthographic rays start on the
    // image plane through the camera position.
    void ray(double px, double py, Vec3& origin, Vec3& direction) const {
        Vec3 r, u, f;
        basis(r, u, f);
        double sx, sy;
        planeOffsets(px, py, sx, sy);
        if (projection == Projection::Perspective) {
            origin = position;
            direction = f + r * sx + u * sy;
        } else {
            origin = position + r * sx + u * sy;
            direction = f;
        }
    }

    // World position of the pixel centre (x, y) at planar view depth `depth`.
    Vec3 worldPosition(double px, double py, double depth) const {
        Vec3 o, d;
        ray(px, py, o, d);
        return o + d * depth;
    }

    // Planar depth of a world point (distance along forward).
    double depthOf(const Vec3& p) const { return dot(p - position, normalize(forward)); }

    // World-space size of one pixel at planar depth `depth`.
    double pixelSizeAt(double depth) const {
        const double h = 2.0 * halfHeight() / (height > 0 ? height : 1);
        return projection == Projection::Perspective ? h * depth : h;
    }
};

inline const char* toString(Camera::Projection p) {
    return p == Camera::Projection::Perspective ? "perspective" : "orthographic";
}

}  // namespace darkroom
