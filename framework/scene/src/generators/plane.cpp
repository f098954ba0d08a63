// `plane`: a square of side `size` around `center`, facing `normal`, split
// into subdivisions^2 quads (two triangles each), e.g. a floor for shadows.
#include "builtin_generators.h"

#include <cmath>

namespace darkroom::generators {

PlaneOptions readPlaneOptions(GeneratorParams& p) {
    PlaneOptions o;
    o.size = p.number("size", o.size, 1e-9, 1e9);
    o.center = p.vec3("center", o.center);
    o.normal = p.vec3("normal", o.normal);
    if (length(o.normal) < 1e-12) p.fail("normal", "must not be the zero vector");
    o.subdivisions = p.integer("subdivisions", o.subdivisions, 1, 4096);
    p.finish();
    return o;
}

SceneObject buildPlane(const PlaneOptions& o) {
    const Vec3 n = normalize(o.normal);
    // Any vector not parallel to n gives the in-plane axes u, v with u x v = n.
    const Vec3 helper = std::abs(n.z) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0};
    const Vec3 u = normalize(cross(helper, n));
    const Vec3 v = cross(n, u);
    SceneObject obj;
    obj.name = "plane";
    obj.representation = Representation::Surface;
    ScalarField height{"height", ScalarField::Association::Point, {}};
    const int s = o.subdivisions;
    for (int j = 0; j <= s; ++j)
        for (int i = 0; i <= s; ++i) {
            const Vec3 p = o.center + u * (o.size * (double(i) / s - 0.5)) + v * (o.size * (double(j) / s - 0.5));
            appendVertex(obj, p, 0);
            height.values.push_back(float(p.z));
        }
    for (int j = 0; j < s; ++j)
        for (int i = 0; i < s; ++i) {
            const auto a = std::uint32_t(j * (s + 1) + i), b = a + 1, c = a + std::uint32_t(s + 1), d = c + 1;
            // Counter-clockwise seen from the side `normal` points to.
            obj.indices.insert(obj.indices.end(), {a, b, d, a, d, c});
        }
    obj.fields = {std::move(height)};
    return obj;
}

}  // namespace darkroom::generators
