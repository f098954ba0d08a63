#include "scene_builders.h"

#include <cmath>
#include <numbers>

namespace darkroom::test {

namespace {
void pushVertex(SceneObject& o, Vec3 p, double r = 0.0) {
    o.vertices.insert(o.vertices.end(), {float(p.x), float(p.y), float(p.z), float(r)});
}
}  // namespace

Vec3 vertex(const SceneObject& obj, std::uint32_t i) {
    return {obj.vertices[4 * i], obj.vertices[4 * i + 1], obj.vertices[4 * i + 2]};
}

SceneObject makeQuad(Vec3 corner, Vec3 e1, Vec3 e2) {
    SceneObject o;
    o.name = "quad";
    pushVertex(o, corner);
    pushVertex(o, corner + e1);
    pushVertex(o, corner + e1 + e2);
    pushVertex(o, corner + e2);
    o.indices = {0, 1, 2, 0, 2, 3};
    ScalarField x{"X", ScalarField::Association::Point, {}};
    for (std::uint32_t i = 0; i < 4; ++i) x.values.push_back(o.vertices[4 * i]);
    o.fields.push_back(x);
    o.fields.push_back({"C", ScalarField::Association::Cell, {10.0f, 20.0f}});
    return o;
}

SceneObject makeSphereMesh(Vec3 c, double r, int rings, int segments) {
    SceneObject o;
    o.name = "sphere-mesh";
    const double pi = std::numbers::pi;
    for (int i = 0; i <= rings; ++i) {
        const double th = pi * i / rings;
        for (int j = 0; j < segments; ++j) {
            const double ph = 2 * pi * j / segments;
            pushVertex(o, c + Vec3{std::sin(th) * std::cos(ph), std::cos(th), std::sin(th) * std::sin(ph)} * r);
        }
    }
    for (int i = 0; i < rings; ++i)
        for (int j = 0; j < segments; ++j) {
            const std::uint32_t a = i * segments + j, b = i * segments + (j + 1) % segments;
            const std::uint32_t c2 = a + segments, d = b + segments;
            o.indices.insert(o.indices.end(), {a, c2, b, b, c2, d});
        }
    ScalarField x{"X", ScalarField::Association::Point, {}};
    for (std::size_t i = 0; i < o.vertexCount(); ++i) x.values.push_back(o.vertices[4 * i]);
    o.fields.push_back(x);
    return o;
}

SceneObject makePoints(const std::vector<Vec3>& centers, double radius) {
    SceneObject o;
    o.name = "points";
    o.representation = Representation::Points;
    ScalarField id{"pointValue", ScalarField::Association::Point, {}};
    for (std::size_t i = 0; i < centers.size(); ++i) {
        pushVertex(o, centers[i], radius);
        id.values.push_back(float(100 + i));
    }
    o.fields.push_back(id);
    return o;
}

SceneObject makeTube(Vec3 a, Vec3 b, double radius, int segments) {
    SceneObject o;
    o.name = "tube";
    o.representation = Representation::Lines;
    ScalarField s{"s", ScalarField::Association::Point, {}};
    for (int i = 0; i <= segments; ++i) {
        const double f = double(i) / segments;
        pushVertex(o, a + (b - a) * f, radius);
        s.values.push_back(float(f));
    }
    for (int i = 0; i < segments; ++i) {
        o.indices.push_back(std::uint32_t(i));
        o.primitiveCell.push_back(0);
    }
    o.fields.push_back(s);
    o.fields.push_back({"line", ScalarField::Association::Cell, {7.0f}});
    return o;
}

Camera perspectiveCamera(Vec3 position, Vec3 target, int w, int h, double fovY) {
    Camera c;
    c.position = position;
    c.forward = normalize(target - position);
    c.up = {0, 1, 0};
    c.projection = Camera::Projection::Perspective;
    c.fovYDegrees = fovY;
    c.width = w;
    c.height = h;
    return c;
}

Camera orthographicCamera(Vec3 position, Vec3 target, int w, int h, double viewHeight) {
    Camera c = perspectiveCamera(position, target, w, h);
    c.projection = Camera::Projection::Orthographic;
    c.viewHeight = viewHeight;
    return c;
}

std::optional<double> intersectPlane(Vec3 o, Vec3 d, Vec3 p, Vec3 n) {
    const double den = dot(d, n);
    if (den == 0) return std::nullopt;
    const double t = dot(p - o, n) / den;
    if (t < 0) return std::nullopt;
    return t;
}

std::optional<double> intersectSphere(Vec3 o, Vec3 d, Vec3 c, double r) {
    const Vec3 oc = o - c;
    const double a = dot(d, d), b = dot(oc, d), cc = dot(oc, oc) - r * r;
    const double disc = b * b - a * cc;
    if (disc < 0) return std::nullopt;
    const double t = (-b - std::sqrt(disc)) / a;
    if (t < 0) return std::nullopt;
    return t;
}

std::optional<double> intersectCylinder(Vec3 o, Vec3 d, Vec3 a, Vec3 b, double r, double* axial) {
    const Vec3 axis = b - a;
    const Vec3 w = normalize(axis);
    const Vec3 oa = o - a;
    const Vec3 dp = d - w * dot(d, w);
    const Vec3 op = oa - w * dot(oa, w);
    const double qa = dot(dp, dp), qb = dot(op, dp), qc = dot(op, op) - r * r;
    const double disc = qb * qb - qa * qc;
    if (qa == 0 || disc < 0) return std::nullopt;
    const double t = (-qb - std::sqrt(disc)) / qa;
    if (t < 0) return std::nullopt;
    if (axial) *axial = dot(o + d * t - a, axis) / dot(axis, axis);
    return t;
}

std::optional<double> intersectTrianglePlane(Vec3 o, Vec3 d, const SceneObject& obj, std::uint32_t tri) {
    const Vec3 p0 = vertex(obj, obj.indices[3 * tri]), p1 = vertex(obj, obj.indices[3 * tri + 1]),
               p2 = vertex(obj, obj.indices[3 * tri + 2]);
    return intersectPlane(o, d, p0, cross(p1 - p0, p2 - p0));
}

}  // namespace darkroom::test
