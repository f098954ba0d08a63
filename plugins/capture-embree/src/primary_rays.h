#pragma once
// Primary ray generation shared by the backend and the benchmark's plain
// Embree loop, so both trace exactly the same rays.
#include <darkroom/camera.h>

namespace darkroom::embree {

// Camera::ray() with the basis computed once per image instead of per ray; the
// arithmetic per ray is the same as Camera::planeOffsets so the rays match the
// camera that is stored with the buffer (world positions reconstruct exactly).
class PrimaryRays {
public:
    explicit PrimaryRays(const Camera& c)
        : pos_(c.position), perspective_(c.projection == Camera::Projection::Perspective),
          width_(c.width), height_(c.height) {
        c.basis(right_, up_, fwd_);
        hh_ = c.halfHeight();
        hw_ = hh_ * (c.height > 0 ? double(c.width) / double(c.height) : 1.0);
    }

    // Ray through the centre of pixel (x, y). Perspective directions have a
    // forward component of 1 (t == planar depth); orthographic rays start on
    // the image plane through the camera position with the unit forward
    // direction (t == planar depth as well).
    void operator()(int x, int y, float org[3], float dir[3]) const {
        const double sx = (2.0 * (x + 0.5) / width_ - 1.0) * hw_;
        const double sy = (1.0 - 2.0 * (y + 0.5) / height_) * hh_;
        Vec3 o, d;
        if (perspective_) {
            o = pos_;
            d = fwd_ + right_ * sx + up_ * sy;
        } else {
            o = pos_ + right_ * sx + up_ * sy;
            d = fwd_;
        }
        org[0] = float(o.x), org[1] = float(o.y), org[2] = float(o.z);
        dir[0] = float(d.x), dir[1] = float(d.y), dir[2] = float(d.z);
    }

private:
    Vec3 pos_, right_, up_, fwd_;
    double hh_ = 1, hw_ = 1;
    bool perspective_;
    int width_, height_;
};

}  // namespace darkroom::embree
