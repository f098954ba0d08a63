#pragma once
// VTK's linear 3D cells: their faces (local corner indices, VTK's point order)
// and their split into tetrahedra. The quadratic cells (24..27) are used by
// their corners, which come first in VTK's order.
#include <array>
#include <cstdint>
#include <vector>

namespace darkroom::volume {

// VTK cell type ids (vtkCellType.h).
enum : int {
    kVertex = 1, kPolyVertex = 2, kLine = 3, kPolyLine = 4, kTriangle = 5, kTriangleStrip = 6, kPolygon = 7,
    kPixel = 8, kQuad = 9, kTetra = 10, kVoxel = 11, kHexahedron = 12, kWedge = 13, kPyramid = 14,
    kQuadraticTetra = 24, kQuadraticHexahedron = 25, kQuadraticWedge = 26, kQuadraticPyramid = 27,
    kPolyhedron = 42
};

bool isVolumeCell(int type);

// The linear cell a 3D type is drawn as (tetra, hexahedron, wedge, pyramid),
// with its corner count; voxels map to hexahedra (see toLinearCorners).
struct LinearCell {
    int type = 0;
    int corners = 0;
};
LinearCell linearCell(int type);

// Reorders a voxel's corners (x fastest) into hexahedron order; other types
// keep their first `corners` ids.
void toLinearCorners(int type, std::vector<std::uint32_t>& ids);

// Faces of a linear 3D cell as local corner indices (3 or 4 each).
struct Face {
    std::array<int, 4> corner;
    int count;
};
const std::vector<Face>& facesOf(int linearType);

}  // namespace darkroom::volume
