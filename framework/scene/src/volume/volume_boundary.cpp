// The boundary surface of a volume: faces of 3D cells that no other cell
// shares (found by sorting the faces by their sorted corner ids), oriented outwards,
// plus the 2D cells the file holds. Image data: the six sides of the grid.
#include "cell_topology.h"
#include "volume_polymesh.h"

#include <darkroom/error.h>

#include <algorithm>

namespace darkroom::volume {
namespace {

struct FaceKey {
    std::array<std::uint32_t, 4> ids;
    bool operator==(const FaceKey&) const = default;
};

// Appends a face's corners so that its normal points away from `inside`.
void emitOriented(const VolumeMesh& v, std::vector<std::uint32_t> corners, const Vec3& inside,
                  std::uint32_t cell, mesh::PolyMesh& out, PointMap& points) {
    Vec3 c{0, 0, 0};
    for (auto id : corners) c = c + v.point(id);
    c = c * (1.0 / double(corners.size()));
    const Vec3 n = cross(v.point(corners[1]) - v.point(corners[0]), v.point(corners[2]) - v.point(corners[0]));
    if (dot(n, c - inside) < 0) std::reverse(corners.begin(), corners.end());
    for (auto id : corners) out.polygons.connectivity.push_back(points.add(id));
    out.polygons.close(cell);
}

void unstructuredBoundary(const VolumeMesh& v, mesh::PolyMesh& out, PointMap& points) {
    // Every face of every 3D cell keyed by its sorted corners; after sorting, a
    // key that occurs once is a boundary face. (Sorting beats a hash table here:
    // measured 3x faster on 663,552 tetrahedra.)
    struct Entry {
        FaceKey key;
        std::uint32_t cell;
        std::uint8_t face;
    };
    std::vector<Entry> entries;
    std::vector<std::uint32_t> ids;
    const std::size_t n = v.cellCount();
    entries.reserve(n * 4);
    for (std::size_t c = 0; c < n; ++c) {
        const int type = v.cell(c, ids);
        if (!isVolumeCell(type)) continue;
        toLinearCorners(type, ids);
        const auto& fs = facesOf(linearCell(type).type);
        for (std::size_t f = 0; f < fs.size(); ++f) {
            Entry e{{{0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu}}, std::uint32_t(c), std::uint8_t(f)};
            for (int i = 0; i < fs[f].count; ++i) e.key.ids[std::size_t(i)] = ids[std::size_t(fs[f].corner[std::size_t(i)])];
            std::sort(e.key.ids.begin(), e.key.ids.end());
            entries.push_back(e);
        }
    }
    std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
        return a.key.ids != b.key.ids ? a.key.ids < b.key.ids : a.cell < b.cell;
    });
    // Emit in cell order so the output does not depend on the sort's tie order.
    std::vector<std::pair<std::uint32_t, std::uint8_t>> boundary;
    for (std::size_t i = 0; i < entries.size();) {
        std::size_t j = i + 1;
        while (j < entries.size() && entries[j].key == entries[i].key) ++j;
        if (j == i + 1) boundary.push_back({entries[i].cell, entries[i].face});
        i = j;
    }
    std::vector<Entry>().swap(entries);
    std::sort(boundary.begin(), boundary.end());
    for (const auto& [c, f] : boundary) {
        const int type = v.cell(c, ids);
        toLinearCorners(type, ids);
        const Face& face = facesOf(linearCell(type).type)[f];
        Vec3 centroid{0, 0, 0};
        for (auto id : ids) centroid = centroid + v.point(id);
        centroid = centroid * (1.0 / double(ids.size()));
        std::vector<std::uint32_t> corners;
        for (int i = 0; i < face.count; ++i) corners.push_back(ids[std::size_t(face.corner[std::size_t(i)])]);
        emitOriented(v, corners, centroid, c, out, points);
    }
    // 2D cells are surfaces already (ParaView's Extract Surface keeps them).
    for (std::size_t c = 0; c < n; ++c) {
        const int type = v.cell(c, ids);
        if (type == kTriangle || type == kPolygon || type == kQuad) {
            for (auto id : ids) out.polygons.connectivity.push_back(points.add(id));
            out.polygons.close(std::uint32_t(c));
        } else if (type == kPixel && ids.size() == 4) {
            for (int i : {0, 1, 3, 2}) out.polygons.connectivity.push_back(points.add(ids[std::size_t(i)]));
            out.polygons.close(std::uint32_t(c));
        }
    }
}

void imageBoundary(const VolumeMesh& v, mesh::PolyMesh& out, PointMap& points) {
    const std::size_t nx = std::size_t(v.dims[0]), ny = std::size_t(v.dims[1]), nz = std::size_t(v.dims[2]);
    const std::size_t cx = nx - 1, cy = ny - 1, cz = nz - 1;
    const Vec3 centre = (v.point(0) + v.point(v.pointCount() - 1)) * 0.5;
    auto pid = [&](std::size_t i, std::size_t j, std::size_t k) { return std::uint32_t(i + nx * (j + ny * k)); };
    auto cid = [&](std::size_t i, std::size_t j, std::size_t k) { return std::uint32_t(i + cx * (j + cy * k)); };
    // For each axis, the two sides; quads between neighbouring grid points on the side.
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
            const std::size_t n[3] = {cx, cy, cz};
            const int a = (axis + 1) % 3, b = (axis + 2) % 3;
            for (std::size_t u = 0; u < n[a]; ++u)
                for (std::size_t w = 0; w < n[b]; ++w) {
                    std::size_t p[4][3], cell[3];
                    const std::size_t du[4] = {0, 1, 1, 0}, dw[4] = {0, 0, 1, 1};
                    for (int q = 0; q < 4; ++q) {
                        p[q][axis] = side ? (axis == 0 ? nx : axis == 1 ? ny : nz) - 1 : 0;
                        p[q][a] = u + du[q];
                        p[q][b] = w + dw[q];
                    }
                    cell[axis] = side ? n[axis] - 1 : 0;
                    cell[a] = u;
                    cell[b] = w;
                    std::vector<std::uint32_t> corners;
                    for (int q = 0; q < 4; ++q) corners.push_back(pid(p[q][0], p[q][1], p[q][2]));
                    emitOriented(v, corners, centre, cid(cell[0], cell[1], cell[2]), out, points);
                }
        }
}

}  // namespace

void buildBoundary(const VolumeMesh& v, mesh::PolyMesh& out, PointMap& points) {
    if (v.isImage()) imageBoundary(v, out, points);
    else unstructuredBoundary(v, out, points);
}

}  // namespace darkroom::volume
