#include "test_meshes.h"

#include "test_support.h"

#include <cmath>
#include <sstream>

namespace darkroom::test {

SceneObject triangleMesh(const std::vector<Vec3>& points, std::vector<std::uint32_t> triangles) {
    SceneObject o;
    o.name = "mesh";
    for (const Vec3& p : points) o.vertices.insert(o.vertices.end(), {float(p.x), float(p.y), float(p.z), 0.0f});
    o.indices = std::move(triangles);
    return o;
}

SceneObject unitCube(const Vec3& origin) {
    std::vector<Vec3> p;
    for (int i = 0; i < 8; ++i) p.push_back(origin + Vec3{double(i & 1), double(i >> 1 & 1), double(i >> 2 & 1)});
    return triangleMesh(p, {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
                       2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5});
}

SceneObject uvSphere(int rings, int segments, double r, const Vec3& centre) {
    const double pi = 3.14159265358979323846;
    std::vector<Vec3> p{centre + Vec3{0, 0, r}};
    for (int i = 1; i < rings; ++i)
        for (int j = 0; j < segments; ++j) {
            const double t = pi * i / rings, f = 2 * pi * j / segments;
            p.push_back(centre + Vec3{r * std::sin(t) * std::cos(f), r * std::sin(t) * std::sin(f), r * std::cos(t)});
        }
    p.push_back(centre + Vec3{0, 0, -r});
    const auto ring = [&](int i, int j) { return std::uint32_t(1 + (i - 1) * segments + (j % segments)); };
    const std::uint32_t south = std::uint32_t(p.size() - 1);
    std::vector<std::uint32_t> t;
    for (int j = 0; j < segments; ++j) {
        t.insert(t.end(), {0, ring(1, j), ring(1, j + 1)});
        for (int i = 1; i + 1 < rings; ++i)
            t.insert(t.end(), {ring(i, j), ring(i + 1, j), ring(i + 1, j + 1), ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)});
        t.insert(t.end(), {ring(rings - 1, j), south, ring(rings - 1, j + 1)});
    }
    return triangleMesh(p, t);
}

void writeObj(const std::string& path, const SceneObject& o) {
    std::ostringstream s;
    s.precision(9);
    for (std::size_t v = 0; v < o.vertexCount(); ++v)
        s << "v " << o.vertices[4 * v] << ' ' << o.vertices[4 * v + 1] << ' ' << o.vertices[4 * v + 2] << '\n';
    for (std::size_t t = 0; t + 2 < o.indices.size(); t += 3)
        s << "f " << o.indices[t] + 1 << ' ' << o.indices[t + 1] + 1 << ' ' << o.indices[t + 2] + 1 << '\n';
    writeText(path, s.str());
}

}  // namespace darkroom::test
