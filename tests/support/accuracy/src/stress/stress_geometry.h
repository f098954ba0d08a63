#pragma once
// Small geometry builders shared by the stress-scene families: grids, boxes,
// spheres, polylines and cameras, each object carrying its colour field.
#include <darkroom/camera.h>
#include <darkroom/math.h>
#include <darkroom/scene.h>

#include <functional>
#include <string>
#include <vector>

namespace darkroom::stress::detail {

constexpr double kPi = 3.14159265358979323846;
constexpr double kFovY = 40.0;  // every family's vertical field of view (degrees)

// A perspective camera at `eye` looking at `target`; `up` need not be
// orthogonal to the view direction but must not be parallel to it.
Camera lookAt(const Vec3& eye, const Vec3& target, const Vec3& up, int width, int height);

// Half the view's vertical extent at planar depth `depth`.
inline double halfViewHeight(const Camera& c, double depth) { return c.halfHeight() * depth; }
inline double aspect(const Camera& c) { return double(c.width) / double(c.height); }

using PointFieldFn = std::function<double(const Vec3&)>;

// A planar (or displaced) grid: vertex (i, j) = origin + us[i] * axisU + vs[j] * axisV
// (+ displace(u, v) * normal when given), two triangles per cell, point field
// `field` evaluated at each vertex position.
SceneObject gridSurface(const std::string& name, const Vec3& origin, const Vec3& axisU, const Vec3& axisV,
                        const std::vector<double>& us, const std::vector<double>& vs, const std::string& field,
                        const PointFieldFn& fieldAt,
                        const std::function<double(double, double)>& displace = {});

// `n` + 1 evenly spaced values from a to b.
std::vector<double> linspace(double a, double b, int n);

// A closed axis-aligned box (then rotated about y by `yawRadians` around its
// centre), four vertices per face so faces stay flat; point field constant.
SceneObject box(const std::string& name, const Vec3& lo, const Vec3& hi, const std::string& field,
                const PointFieldFn& fieldAt, double yawRadians = 0.0);

// A closed UV sphere triangle mesh with `rings` latitude bands and 2 * rings
// longitude segments.
SceneObject sphereMesh(const std::string& name, const Vec3& centre, double radius, int rings,
                       const std::string& field, const PointFieldFn& fieldAt);

// Appends vertex (x, y, z, r) to an object.
inline void pushVertex(SceneObject& o, const Vec3& p, double radius = 0.0) {
    o.vertices.push_back(float(p.x));
    o.vertices.push_back(float(p.y));
    o.vertices.push_back(float(p.z));
    o.vertices.push_back(float(radius));
}

inline Vec3 vertexAt(const SceneObject& o, std::size_t i) {
    return {o.vertices[4 * i], o.vertices[4 * i + 1], o.vertices[4 * i + 2]};
}

}  // namespace darkroom::stress::detail
