#pragma once
// Volumes made in code for the volume tests: grids of unit cubes cut into
// each kind of 3D cell, with point fields given as functions of position.
#include <darkroom/scene/volume.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace darkroom::test {

using Field = std::function<double(const Vec3&)>;

// An n^3 grid of unit-size cubes over [0, n]^3, each cube as `kind` cells:
// "hex", "voxel", "tet" (six Kuhn tetrahedra), "wedge" (two prisms),
// "pyramid" (six pyramids on the faces, apex at an extra centre point).
VolumeMesh cubes(int n, const std::string& kind, const std::vector<std::pair<std::string, Field>>& fields);

}  // namespace darkroom::test
