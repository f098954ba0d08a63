// VolumeMesh accessors: implicit image-data points and voxels, explicit cells.
#include "cell_topology.h"

#include <darkroom/scene/volume.h>

namespace darkroom {

const char* toString(VolumeRepresentation::Kind k) {
    switch (k) {
        case VolumeRepresentation::Kind::Boundary: return "boundary";
        case VolumeRepresentation::Kind::Isosurface: return "isosurface";
        case VolumeRepresentation::Kind::Slice: return "slice";
    }
    return "?";
}

std::size_t VolumeMesh::pointCount() const {
    if (isImage()) return std::size_t(dims[0]) * std::size_t(dims[1]) * std::size_t(dims[2]);
    return points.size() / 3;
}

std::size_t VolumeMesh::cellCount() const {
    if (isImage()) return std::size_t(dims[0] - 1) * std::size_t(dims[1] - 1) * std::size_t(dims[2] - 1);
    return types.size();
}

Vec3 VolumeMesh::point(std::size_t id) const {
    if (!isImage()) return {points[3 * id], points[3 * id + 1], points[3 * id + 2]};
    const std::size_t nx = std::size_t(dims[0]), ny = std::size_t(dims[1]);
    const double i = double(id % nx), j = double((id / nx) % ny), k = double(id / (nx * ny));
    const Vec3 s{spacing.x * i, spacing.y * j, spacing.z * k};
    const auto& d = direction;
    return {origin.x + d[0] * s.x + d[1] * s.y + d[2] * s.z, origin.y + d[3] * s.x + d[4] * s.y + d[5] * s.z,
            origin.z + d[6] * s.x + d[7] * s.y + d[8] * s.z};
}

int VolumeMesh::cell(std::size_t c, std::vector<std::uint32_t>& ids) const {
    if (!isImage()) {
        ids.assign(connectivity.begin() + offsets[c], connectivity.begin() + offsets[c + 1]);
        return types[c];
    }
    const std::size_t cx = std::size_t(dims[0] - 1), cy = std::size_t(dims[1] - 1);
    const std::size_t i = c % cx, j = (c / cx) % cy, k = c / (cx * cy);
    const std::size_t nx = std::size_t(dims[0]), nxy = nx * std::size_t(dims[1]);
    const std::size_t base = i + j * nx + k * nxy;
    // Hexahedron order: bottom face counter-clockwise, then the top face.
    const std::size_t corner[8] = {base,      base + 1,      base + 1 + nx,      base + nx,
                                   base + nxy, base + 1 + nxy, base + 1 + nx + nxy, base + nx + nxy};
    ids.assign(corner, corner + 8);
    return volume::kHexahedron;
}

std::size_t VolumeMesh::volumeCellCount() const {
    if (isImage()) return cellCount();
    std::size_t n = 0;
    for (std::uint8_t t : types) n += volume::isVolumeCell(t);
    return n;
}

}  // namespace darkroom
