#pragma once
// Volume representations as the mesh readers' PolyMesh, so that
// mesh::buildSceneObjects makes the SceneObject (field expansion, checks).
#include "../poly_mesh.h"

#include <darkroom/scene/volume.h>

#include <cstdint>
#include <vector>

namespace darkroom::volume {

// Volume points used by the output, numbered in order of first use.
class PointMap {
public:
    explicit PointMap(std::size_t volumePoints) : local_(volumePoints, kNone) {}
    std::uint32_t add(std::uint32_t id) {
        if (local_[id] == kNone) {
            local_[id] = std::uint32_t(source_.size());
            source_.push_back(id);
        }
        return local_[id];
    }
    const std::vector<std::uint32_t>& source() const { return source_; }

private:
    static constexpr std::uint32_t kNone = 0xffffffffu;
    std::vector<std::uint32_t> local_;
    std::vector<std::uint32_t> source_;
};

// out.points and out.pointData from the volume points `points` lists.
void takePoints(const VolumeMesh& v, const PointMap& points, mesh::PolyMesh& out);

// Boundary faces into out.polygons (cell ids = the volume's cells).
void buildBoundary(const VolumeMesh& v, mesh::PolyMesh& out, PointMap& points);

// Isosurfaces or slices: new points on cut edges with every point array
// interpolated, triangles into out.polygons (cell ids = the volume's cells).
void buildContour(const VolumeMesh& v, const VolumeRepresentation& r, mesh::PolyMesh& out);

}  // namespace darkroom::volume
