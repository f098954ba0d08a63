#pragma once
// Depth buffers ray traced analytically in the tests (no capture backend), so
// the known answers depend on nothing the pass computes.
#include "test_support.h"

#include <darkroom/buffer.h>
#include <darkroom/camera.h>

#include <cmath>
#include <functional>
#include <limits>

namespace ssao_test {

using darkroom::Camera;
using darkroom::Vec3;

inline Camera lookAt(Vec3 position, Vec3 target, int w, int h, double fov = 40.0) {
    Camera c;
    c.position = position;
    c.forward = darkroom::normalize(target - position);
    c.up = {0, 1, 0};
    c.fovYDegrees = fov;
    c.width = w;
    c.height = h;
    return c;
}

// Planar depth of the nearest hit of ray (o, d) where d has unit forward
// component (Camera::ray), +inf for none: `hit` returns the ray parameter or
// +inf.
using HitFn = std::function<double(const Vec3& o, const Vec3& d)>;

inline std::shared_ptr<darkroom::WritableBuffer> depthImage(const Camera& cam, const HitFn& hit) {
    auto b = darkroom::test::makeImage(cam.width, cam.height, {"Z"}, [&](int x, int y, int) {
        Vec3 o, d;
        cam.ray(x + 0.5, y + 0.5, o, d);
        const double t = hit(o, d);
        // Orthographic rays have unit direction; their parameter is also planar depth.
        return std::isfinite(t) ? float(t) : std::numeric_limits<float>::infinity();
    });
    b->metadata().camera = cam;
    return b;
}

inline double planeHit(const Vec3& o, const Vec3& d, const Vec3& point, const Vec3& normal) {
    const double den = darkroom::dot(d, normal);
    if (std::fabs(den) < 1e-12) return std::numeric_limits<double>::infinity();
    const double t = darkroom::dot(point - o, normal) / den;
    return t > 0 ? t : std::numeric_limits<double>::infinity();
}

inline double sphereHit(const Vec3& o, const Vec3& d, const Vec3& c, double r) {
    const Vec3 oc = o - c;
    const double a = darkroom::dot(d, d), b = darkroom::dot(oc, d), cc = darkroom::dot(oc, oc) - r * r;
    const double disc = b * b - a * cc;
    if (disc < 0) return std::numeric_limits<double>::infinity();
    const double t = (-b - std::sqrt(disc)) / a;
    return t > 0 ? t : std::numeric_limits<double>::infinity();
}

// Floor y = 0 (x >= 0) meeting a wall x = 0 (y >= 0): a 90-degree corner,
// infinite in z; solid where x < 0 or y < 0.
inline double cornerHit(const Vec3& o, const Vec3& d) {
    double best = std::numeric_limits<double>::infinity();
    const double tf = planeHit(o, d, {0, 0, 0}, {0, 1, 0});
    if (std::isfinite(tf) && o.x + tf * d.x >= 0) best = tf;
    const double tw = planeHit(o, d, {0, 0, 0}, {1, 0, 0});
    if (std::isfinite(tw) && o.y + tw * d.y >= 0) best = std::min(best, tw);
    return best;
}

}  // namespace ssao_test
