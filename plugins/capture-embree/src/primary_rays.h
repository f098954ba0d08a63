#pragma once
// Primary ray generation shared by the backend and the benchmark's plain
// Embree loop, so both trace exactly the same rays.
#include <darkroom/camera.h>

#include <vector>

namespace darkroom::embree {

// Camera::ray() with the basis computed once per image instead of per ray; the
// arithmetic per ray is the same as Camera::planeOffsets so the rays match the
// camera that is stored with the buffer (world positions reconstruct exactly).
// The part of a ray that depends on the column (forward + right * sx, or
// position + right * sx) and the part that depends on the row (up * sy) are
// tabulated, in double precision, so a ray costs three additions.
class PrimaryRays {
public:
    explicit PrimaryRays(const Camera& c)
        : pos_(c.position), perspective_(c.projection == Camera::Projection::Perspective),
          column_(std::size_t(c.width > 0 ? c.width : 0)), row_(std::size_t(c.height > 0 ? c.height : 0)) {
        Vec3 right, up;
        c.basis(right, up, fwd_);
        const double hh = c.halfHeight();
        const double hw = hh * (c.height > 0 ? double(c.width) / double(c.height) : 1.0);
        for (int x = 0; x < c.width; ++x) {
            const double sx = (2.0 * (x + 0.5) / c.width - 1.0) * hw;
            column_[std::size_t(x)] = (perspective_ ? fwd_ : pos_) + right * sx;
        }
        for (int y = 0; y < c.height; ++y) {
            const double sy = (1.0 - 2.0 * (y + 0.5) / c.height) * hh;
            row_[std::size_t(y)] = up * sy;
        }
    }

    // Ray through the centre of pixel (x, y). Perspective directions have a
    // forward component of 1 (t == planar depth); orthographic rays start on
    // the image plane through the camera position with the unit forward
    // direction (t == planar depth as well).
    void operator()(int x, int y, float org[3], float dir[3]) const {
        const Vec3 v = column_[std::size_t(x)] + row_[std::size_t(y)];
        const Vec3& o = perspective_ ? pos_ : v;
        const Vec3& d = perspective_ ? v : fwd_;
        org[0] = float(o.x), org[1] = float(o.y), org[2] = float(o.z);
        dir[0] = float(d.x), dir[1] = float(d.y), dir[2] = float(d.z);
    }

private:
    Vec3 pos_, fwd_;
    bool perspective_;
    std::vector<Vec3> column_, row_;
};

}  // namespace darkroom::embree
