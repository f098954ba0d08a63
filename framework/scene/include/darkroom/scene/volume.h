#pragma once
// Volumes for capture: VTK unstructured grids with 3D cells (.vtu:
// tetrahedra, hexahedra, voxels, wedges, pyramids; their quadratic versions
// by their corners) and VTK image data (.vti), made drawable by a
// representation chosen in the scene file — the boundary surface, isosurfaces
// of a point field at listed values, or slices by planes — each giving one
// surface object with the volume's fields (point fields interpolated, cell
// fields of the cell each triangle lies in). docs/scene-format.md.
#include <darkroom/export.h>
#include <darkroom/math.h>
#include <darkroom/scene.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace darkroom {

// One data array; `components` values per tuple.
struct VolumeArray {
    std::string name;
    int components = 1;
    std::vector<float> values;
};

// A volume as read. Either explicit (unstructured: points and cells in VTK's
// types and point order) or implicit (image data: dims > 0).
struct VolumeMesh {
    std::string source;  // the file, for messages

    // Unstructured grid.
    std::vector<float> points;                // x, y, z per point
    std::vector<std::uint32_t> offsets{0};    // cell c spans [offsets[c], offsets[c+1]) of connectivity
    std::vector<std::uint32_t> connectivity;  // point ids
    std::vector<std::uint8_t> types;          // VTK cell type per cell

    // Image data: dims[0] x dims[1] x dims[2] points, i fastest; point (i, j, k)
    // at origin + direction (spacing * (i, j, k)); cells are the voxels between them.
    std::array<int, 3> dims{0, 0, 0};
    Vec3 origin{0, 0, 0};
    Vec3 spacing{1, 1, 1};
    std::array<double, 9> direction{1, 0, 0, 0, 1, 0, 0, 0, 1};  // row-major 3 x 3

    std::vector<VolumeArray> pointData, cellData;

    bool isImage() const { return dims[0] > 0; }
    DARKROOM_API std::size_t pointCount() const;
    DARKROOM_API std::size_t cellCount() const;
    DARKROOM_API Vec3 point(std::size_t id) const;
    // The VTK type of cell c and its point ids in VTK order (a voxel of image
    // data is returned as VTK_HEXAHEDRON 12, corners in hexahedron order).
    DARKROOM_API int cell(std::size_t c, std::vector<std::uint32_t>& ids) const;
    // Number of cells with a 3D type (tetra 10, voxel 11, hexahedron 12, wedge 13,
    // pyramid 14, quadratic 24..27); all cells for image data.
    DARKROOM_API std::size_t volumeCellCount() const;
};

struct SlicePlane {
    Vec3 origin{0, 0, 0};
    Vec3 normal{0, 0, 1};
};

// How a volume is drawn (ParaView's names: Extract Surface, Contour, Slice).
struct VolumeRepresentation {
    enum class Kind : std::uint8_t { Boundary, Isosurface, Slice };
    Kind kind = Kind::Boundary;
    std::string contourBy;           // isosurface: the point field
    std::vector<double> isovalues;   // isosurface: one or more values
    std::vector<SlicePlane> planes;  // slice: one or more planes
    // Isosurface: give each vertex the field's gradient as its shading
    // normal (reversed, high to low), as the point fields N.x, N.y, N.z
    // (vertex_normals.h). Costs a gradient pass over the volume.
    bool gradientNormals = false;
};

DARKROOM_API const char* toString(VolumeRepresentation::Kind k);

// Reads .vtu (every cell kept, unlike readMesh) or .vti (ImageData, one
// piece, 3D: at least 2 points on each axis). Throws darkroom::Error naming
// file:line and what was expected. `warnings` receives notes on cells that
// cannot be used (polyhedra, higher-order Lagrange cells).
DARKROOM_API VolumeMesh readVolume(const std::string& path, std::vector<std::string>* warnings = nullptr);

// True for .vti, and for .vtu files whose cells include 3D ones (cheap: reads
// the file; callers that go on to readVolume read it twice).
DARKROOM_API bool isVolumeFile(const std::string& path);

// The surface of `r` as one object named `name` (triangles). Point arrays
// become point fields (interpolated along the cut edges for isosurfaces and
// slices), cell arrays cell fields of the cell each triangle came from;
// multi-component arrays become the magnitude plus one field per component,
// as readMesh does. Boundary: the faces of 3D cells that no other cell shares,
// plus the file's 2D cells. An isosurface of a field that is not a point array,
// or an empty result, is an error naming the file and listing what exists.
DARKROOM_API SceneObject volumeSurface(const VolumeMesh& volume, const VolumeRepresentation& r,
                                       const std::string& name);

}  // namespace darkroom
