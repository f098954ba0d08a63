#pragma once
// Level-set extraction by marching tetrahedra on a regular grid. Each cube is
// cut into the six Kuhn tetrahedra around its main diagonal; neighbouring
// cubes then split shared faces the same way, so the mesh is watertight
// without any case table, and the two-slice edge caches weld every vertex.
#include <darkroom/export.h>
#include <darkroom/math.h>

#include <cstdint>
#include <functional>
#include <vector>

namespace darkroom::generators {

struct LevelSetMesh {
    std::vector<Vec3> positions;
    // Three indices per triangle, counter-clockwise seen from outside: the
    // normal (v1 - v0) x (v2 - v0) points from f > isovalue towards f < isovalue.
    std::vector<std::uint32_t> triangles;
};

struct LevelSetGrid {
    Vec3 lo{-1, -1, -1};
    Vec3 hi{1, 1, 1};
    int samples = 64;  // per axis, >= 2
};

// `refine`: move each vertex from the linear interpolation onto the exact
// level set of f along its grid edge (a few bracketed regula falsi steps),
// so vertices lie on the surface to ~1e-9 instead of O(h^2).
DARKROOM_API LevelSetMesh extractLevelSet(const std::function<double(const Vec3&)>& f, const LevelSetGrid& grid,
                             double isovalue, bool refine);

}  // namespace darkroom::generators
