#include "stress_geometry.h"

#include <cmath>

namespace darkroom::stress::detail {

Camera lookAt(const Vec3& eye, const Vec3& target, const Vec3& up, int width, int height) {
    Camera c;
    c.position = eye;
    c.forward = normalize(target - eye);
    c.up = up;
    c.projection = Camera::Projection::Perspective;
    c.fovYDegrees = kFovY;
    c.width = width;
    c.height = height;
    return c;
}

std::vector<double> linspace(double a, double b, int n) {
    std::vector<double> v(std::size_t(n) + 1);
    for (int i = 0; i <= n; ++i) v[std::size_t(i)] = a + (b - a) * double(i) / double(n);
    v.back() = b;  // exact end point, whatever the rounding
    return v;
}

SceneObject gridSurface(const std::string& name, const Vec3& origin, const Vec3& axisU, const Vec3& axisV,
                        const std::vector<double>& us, const std::vector<double>& vs, const std::string& field,
                        const PointFieldFn& fieldAt, const std::function<double(double, double)>& displace) {
    SceneObject o;
    o.name = name;
    o.representation = Representation::Surface;
    const std::size_t nu = us.size(), nv = vs.size();
    const Vec3 normal = normalize(cross(axisU, axisV));
    ScalarField f{field, ScalarField::Association::Point, {}};
    o.vertices.reserve(nu * nv * 4);
    f.values.reserve(nu * nv);
    for (std::size_t j = 0; j < nv; ++j)
        for (std::size_t i = 0; i < nu; ++i) {
            Vec3 p = origin + axisU * us[i] + axisV * vs[j];
            if (displace) p = p + normal * displace(us[i], vs[j]);
            pushVertex(o, p);
            f.values.push_back(float(fieldAt(p)));
        }
    o.indices.reserve((nu - 1) * (nv - 1) * 6);
    for (std::size_t j = 0; j + 1 < nv; ++j)
        for (std::size_t i = 0; i + 1 < nu; ++i) {
            const auto a = std::uint32_t(j * nu + i), b = a + 1, c = std::uint32_t(a + nu), d = c + 1;
            o.indices.insert(o.indices.end(), {a, b, d, a, d, c});
        }
    o.fields.push_back(std::move(f));
    return o;
}

SceneObject box(const std::string& name, const Vec3& lo, const Vec3& hi, const std::string& field,
                const PointFieldFn& fieldAt, double yawRadians) {
    SceneObject o;
    o.name = name;
    o.representation = Representation::Surface;
    const Vec3 c = (lo + hi) * 0.5;
    const double cy = std::cos(yawRadians), sy = std::sin(yawRadians);
    auto corner = [&](int bits) {
        const Vec3 p{(bits & 1) ? hi.x : lo.x, (bits & 2) ? hi.y : lo.y, (bits & 4) ? hi.z : lo.z};
        const Vec3 d = p - c;
        return c + Vec3{cy * d.x + sy * d.z, d.y, -sy * d.x + cy * d.z};
    };
    // Each face as four corner indices (bit masks), counter-clockwise from outside.
    static const int faces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                    {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    ScalarField f{field, ScalarField::Association::Point, {}};
    for (const auto& face : faces) {
        const auto base = std::uint32_t(o.vertexCount());
        for (int k = 0; k < 4; ++k) {
            const Vec3 p = corner(face[k]);
            pushVertex(o, p);
            f.values.push_back(float(fieldAt(p)));
        }
        o.indices.insert(o.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    o.fields.push_back(std::move(f));
    return o;
}

SceneObject sphereMesh(const std::string& name, const Vec3& centre, double radius, int rings,
                       const std::string& field, const PointFieldFn& fieldAt) {
    const int segs = 2 * rings;
    std::vector<double> us = linspace(0.0, 2.0 * kPi, segs), vs = linspace(0.0, kPi, rings);
    // A grid in (longitude, colatitude), wrapped onto the sphere; the poles
    // and the seam repeat vertices, which leaves degenerate but harmless
    // triangles at the poles and no crack at the seam (same float positions).
    SceneObject o;
    o.name = name;
    o.representation = Representation::Surface;
    ScalarField f{field, ScalarField::Association::Point, {}};
    const std::size_t nu = us.size();
    for (double v : vs)
        for (double u : us) {
            const Vec3 p = centre + Vec3{std::sin(v) * std::cos(u), std::cos(v), -std::sin(v) * std::sin(u)} * radius;
            pushVertex(o, p);
            f.values.push_back(float(fieldAt(p)));
        }
    for (std::size_t j = 0; j + 1 < vs.size(); ++j)
        for (std::size_t i = 0; i + 1 < nu; ++i) {
            const auto a = std::uint32_t(j * nu + i), b = a + 1, c = std::uint32_t(a + nu), d = c + 1;
            if (j != 0) o.indices.insert(o.indices.end(), {a, c, b});
            if (j + 2 != vs.size()) o.indices.insert(o.indices.end(), {b, c, d});
        }
    o.fields.push_back(std::move(f));
    return o;
}

}  // namespace darkroom::stress::detail
