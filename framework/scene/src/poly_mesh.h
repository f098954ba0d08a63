#pragma once
// The reader-neutral model every mesh reader fills: VTK-style points, cells in
// four groups and point/cell arrays. buildSceneObjects() turns it into the
// ray-tracer-ready SceneObjects (triangles, segments, spheres) in one place so
// fan triangulation, strips and cell-data mapping behave the same for PLY,
// OBJ, legacy VTK and VTK XML.
#include <darkroom/scene.h>

#include <cstdint>
#include <string>
#include <vector>

namespace darkroom::mesh {

// Marks a restart inside a triangle strip (PLY's -1) without starting a new cell.
inline constexpr std::uint32_t kStripRestart = 0xffffffffu;

struct CellList {
    std::vector<std::uint32_t> offsets{0};  // cell i spans [offsets[i], offsets[i+1])
    std::vector<std::uint32_t> connectivity;
    std::vector<std::uint32_t> cellIds;  // index into the cell arrays, one per cell

    std::size_t size() const { return offsets.size() - 1; }
    void close(std::uint32_t cellId) {
        offsets.push_back(static_cast<std::uint32_t>(connectivity.size()));
        cellIds.push_back(cellId);
    }
};

// One data array; `components` values per tuple.
struct DataArray {
    std::string name;
    int components = 1;
    std::vector<float> values;
};

struct PolyMesh {
    std::string source;          // file name for messages
    std::vector<float> points;   // x, y, z per point
    CellList vertices, lines, polygons, strips;
    std::size_t cellCount = 0;   // size of every cell array
    std::vector<DataArray> pointData, cellData;

    std::size_t pointCount() const { return points.size() / 3; }
};

// Renumbers a surface's `indices` (each below `pointCount`) to the points
// they use, in the order of their first use, so that one surface gets one
// numbering whichever format it was read from; points no triangle uses are
// dropped (they would widen the bounds a camera frames). Returns each mesh
// point's new number, kStripRestart for a dropped point; `used` receives
// how many were kept.
std::vector<std::uint32_t> renumberByFirstUse(std::vector<std::uint32_t>& indices, std::size_t pointCount,
                                              std::size_t& used);

// Validates indices and array sizes (throwing darkroom::Error naming `source`)
// and builds up to three objects: the surface (polygons + strips), the lines
// and the vertex cells; a mesh without any cell becomes one point cloud.
// Multi-component arrays become `<name>` (magnitude) plus `<name>_0`, ...
// `warnings` (optional) receives notes such as skipped cells.
std::vector<SceneObject> buildSceneObjects(const PolyMesh& mesh, const std::string& name);

}  // namespace darkroom::mesh
