#pragma once
// Helpers for the stress-scene tests: projection of world points and a
// brute-force ray caster (triangles, spheres, round segments) so coverage is
// checked without any capture backend.
#include <darkroom/camera.h>
#include <darkroom/scene.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace darkroom::stress_test {

inline Vec3 vertex(const SceneObject& o, std::size_t i) {
    return {o.vertices[4 * i], o.vertices[4 * i + 1], o.vertices[4 * i + 2]};
}
inline double radiusOf(const SceneObject& o, std::size_t i) { return o.vertices[4 * i + 3]; }

// Continuous pixel coordinates of a world point; false when behind the camera.
inline bool project(const Camera& c, const Vec3& p, double& px, double& py) {
    Vec3 r, u, f;
    c.basis(r, u, f);
    const Vec3 d = p - c.position;
    const double z = dot(d, f);
    if (z <= 0) return false;
    const double hh = c.halfHeight(), hw = hh * double(c.width) / double(c.height);
    px = (dot(d, r) / z / hw + 1.0) * 0.5 * c.width;
    py = (1.0 - dot(d, u) / z / hh) * 0.5 * c.height;
    return true;
}

constexpr double kMiss = std::numeric_limits<double>::infinity();

inline double hitTriangle(const Vec3& o, const Vec3& d, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 e1 = b - a, e2 = c - a, p = cross(d, e2);
    const double det = dot(e1, p);
    if (std::abs(det) < 1e-300) return kMiss;
    const double inv = 1.0 / det;
    const Vec3 s = o - a;
    const double u = dot(s, p) * inv;
    if (u < 0 || u > 1) return kMiss;
    const Vec3 q = cross(s, e1);
    const double v = dot(d, q) * inv;
    if (v < 0 || u + v > 1) return kMiss;
    const double t = dot(e2, q) * inv;
    return t > 0 ? t : kMiss;
}

inline double hitSphere(const Vec3& o, const Vec3& d, const Vec3& c, double r) {
    const Vec3 oc = o - c;
    const double a = dot(d, d), b = dot(oc, d), cc = dot(oc, oc) - r * r, disc = b * b - a * cc;
    if (disc < 0) return kMiss;
    const double t = (-b - std::sqrt(disc)) / a;
    return t > 0 ? t : kMiss;
}

// Whether the ray passes within the (interpolated) radius of a segment:
// closest approach of two lines, clamped to the segment. Enough for coverage.
inline double hitSegment(const Vec3& o, const Vec3& d, const Vec3& p0, double r0, const Vec3& p1, double r1) {
    const Vec3 e = p1 - p0, w = o - p0;
    const double a = dot(d, d), b = dot(d, e), c = dot(e, e), dd = dot(d, w), ee = dot(e, w);
    const double den = a * c - b * b;
    double s = den > 1e-300 ? (a * ee - b * dd) / den : 0.0;
    s = std::clamp(s, 0.0, 1.0);
    const double t = (b * s - dd) / a;
    if (t <= 0) return kMiss;
    const Vec3 gap = (o + d * t) - (p0 + e * s);
    return length(gap) <= r0 + (r1 - r0) * s ? t : kMiss;
}

// Nearest hit parameter of a ray against a whole scene (kMiss if none).
inline double castRay(const Scene& scene, const Vec3& o, const Vec3& d) {
    double best = kMiss;
    for (const auto& obj : scene.objects) {
        switch (obj.representation) {
            case Representation::Surface:
                for (std::size_t i = 0; i + 2 < obj.indices.size(); i += 3)
                    best = std::min(best, hitTriangle(o, d, vertex(obj, obj.indices[i]), vertex(obj, obj.indices[i + 1]),
                                                      vertex(obj, obj.indices[i + 2])));
                break;
            case Representation::Points:
                for (std::size_t i = 0; i < obj.vertexCount(); ++i)
                    best = std::min(best, hitSphere(o, d, vertex(obj, i), radiusOf(obj, i)));
                break;
            case Representation::Lines:
                for (auto i : obj.indices)
                    best = std::min(best, hitSegment(o, d, vertex(obj, i), radiusOf(obj, i), vertex(obj, i + 1),
                                                     radiusOf(obj, i + 1)));
                break;
        }
    }
    return best;
}

// Share of an n x n grid of pixel-centred rays that hit something.
inline double coverage(const Scene& scene, const Camera& camera, int n) {
    int hits = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            Vec3 o, d;
            camera.ray((i + 0.5) * camera.width / n, (j + 0.5) * camera.height / n, o, d);
            if (castRay(scene, o, d) < kMiss) ++hits;
        }
    return double(hits) / double(n * n);
}

}  // namespace darkroom::stress_test
