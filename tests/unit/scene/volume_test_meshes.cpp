#include "volume_test_meshes.h"

namespace darkroom::test {

// An n^3 grid of unit-size cubes over [0, n]^3, each cube as `kind` cells:
// "hex", "voxel", "tet" (six Kuhn tetrahedra), "wedge" (two prisms),
// "pyramid" (six pyramids on the faces, apex at an extra centre point).
VolumeMesh cubes(int n, const std::string& kind, const std::vector<std::pair<std::string, Field>>& fields) {
    VolumeMesh v;
    v.source = "test " + kind;
    const int m = n + 1;
    auto id = [&](int i, int j, int k) { return std::uint32_t(i + m * (j + m * k)); };
    for (int k = 0; k < m; ++k)
        for (int j = 0; j < m; ++j)
            for (int i = 0; i < m; ++i) v.points.insert(v.points.end(), {float(i), float(j), float(k)});
    auto add = [&](int type, std::initializer_list<std::uint32_t> ids) {
        v.connectivity.insert(v.connectivity.end(), ids);
        v.offsets.push_back(std::uint32_t(v.connectivity.size()));
        v.types.push_back(std::uint8_t(type));
    };
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                // Corners in hexahedron order.
                const std::uint32_t c[8] = {id(i, j, k),         id(i + 1, j, k),         id(i + 1, j + 1, k),
                                            id(i, j + 1, k),     id(i, j, k + 1),         id(i + 1, j, k + 1),
                                            id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
                if (kind == "hex") {
                    add(12, {c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]});
                } else if (kind == "voxel") {
                    add(11, {c[0], c[1], c[3], c[2], c[4], c[5], c[7], c[6]});
                } else if (kind == "tet") {
                    // Kuhn: paths 0 -> 6 through each axis order (corner 6 is opposite 0).
                    const int paths[6][2] = {{1, 2}, {1, 5}, {3, 2}, {3, 7}, {4, 5}, {4, 7}};
                    for (const auto& p : paths) add(10, {c[0], c[p[0]], c[p[1]], c[6]});
                } else if (kind == "wedge") {
                    add(13, {c[0], c[1], c[2], c[4], c[5], c[6]});
                    add(13, {c[0], c[2], c[3], c[4], c[6], c[7]});
                } else if (kind == "pyramid") {
                    const std::uint32_t centre = std::uint32_t(v.points.size() / 3);
                    v.points.insert(v.points.end(), {float(i) + 0.5f, float(j) + 0.5f, float(k) + 0.5f});
                    const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {3, 7, 6, 2}, {0, 4, 7, 3}, {1, 2, 6, 5}};
                    for (const auto& f : faces) add(14, {c[f[0]], c[f[1]], c[f[2]], c[f[3]], centre});
                }
            }
    for (const auto& [name, f] : fields) {
        VolumeArray a{name, 1, {}};
        for (std::size_t p = 0; p < v.points.size() / 3; ++p)
            a.values.push_back(float(f({v.points[3 * p], v.points[3 * p + 1], v.points[3 * p + 2]})));
        v.pointData.push_back(std::move(a));
    }
    VolumeArray cellIndex{"cell", 1, {}};
    for (std::size_t c = 0; c < v.types.size(); ++c) cellIndex.values.push_back(float(c));
    v.cellData.push_back(std::move(cellIndex));
    return v;
}

}  // namespace darkroom::test
