#include "cell_topology.h"

namespace darkroom::volume {

bool isVolumeCell(int type) {
    return (type >= kTetra && type <= kPyramid) || (type >= kQuadraticTetra && type <= kQuadraticPyramid);
}

LinearCell linearCell(int type) {
    switch (type) {
        case kTetra: case kQuadraticTetra: return {kTetra, 4};
        case kVoxel: case kHexahedron: case kQuadraticHexahedron: return {kHexahedron, 8};
        case kWedge: case kQuadraticWedge: return {kWedge, 6};
        case kPyramid: case kQuadraticPyramid: return {kPyramid, 5};
        default: return {0, 0};
    }
}

void toLinearCorners(int type, std::vector<std::uint32_t>& ids) {
    if (type == kVoxel && ids.size() == 8) {
        // Voxel corners run x fastest (0 1 2 3 = (0,0) (1,0) (0,1) (1,1)); a hexahedron's go around.
        const std::vector<std::uint32_t> v = ids;
        ids = {v[0], v[1], v[3], v[2], v[4], v[5], v[7], v[6]};
        return;
    }
    const int n = linearCell(type).corners;
    if (n > 0 && ids.size() > std::size_t(n)) ids.resize(std::size_t(n));
}

const std::vector<Face>& facesOf(int linearType) {
    // VTK's face lists (vtkTetra, vtkHexahedron, vtkWedge, vtkPyramid); their
    // orientation does not matter here: boundary faces are oriented outwards
    // from the cell's centroid when they are emitted.
    static const std::vector<Face> tetra{{{0, 1, 3, 0}, 3}, {{1, 2, 3, 0}, 3}, {{2, 0, 3, 0}, 3}, {{0, 2, 1, 0}, 3}};
    static const std::vector<Face> hexahedron{{{0, 4, 7, 3}, 4}, {{1, 2, 6, 5}, 4}, {{0, 1, 5, 4}, 4},
                                              {{3, 7, 6, 2}, 4}, {{0, 3, 2, 1}, 4}, {{4, 5, 6, 7}, 4}};
    static const std::vector<Face> wedge{{{0, 1, 2, 0}, 3}, {{3, 5, 4, 0}, 3}, {{0, 3, 4, 1}, 4},
                                         {{1, 4, 5, 2}, 4}, {{2, 5, 3, 0}, 4}};
    static const std::vector<Face> pyramid{{{0, 3, 2, 1}, 4}, {{0, 1, 4, 0}, 3}, {{1, 2, 4, 0}, 3},
                                           {{2, 3, 4, 0}, 3}, {{3, 0, 4, 0}, 3}};
    static const std::vector<Face> none;
    switch (linearType) {
        case kTetra: return tetra;
        case kHexahedron: return hexahedron;
        case kWedge: return wedge;
        case kPyramid: return pyramid;
        default: return none;
    }
}

}  // namespace darkroom::volume
