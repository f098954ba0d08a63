#pragma once
// Triangle meshes made in code, with known normals, for the tests of vertex
// normals and their capture: a cube (flat faces, sharp edges) and a UV
// sphere (smooth, facets tilted by about half the angle between rings).
#include <darkroom/math.h>
#include <darkroom/scene.h>

#include <cstdint>
#include <string>
#include <vector>

namespace darkroom::test {

// A surface of the given points (radius 0) and triangles (3 indices each).
SceneObject triangleMesh(const std::vector<Vec3>& points, std::vector<std::uint32_t> triangles);

// The unit cube [0, 1]^3 moved by `origin`, two triangles a face, wound
// outwards; vertex i at origin + (i & 1, i >> 1 & 1, i >> 2 & 1).
SceneObject unitCube(const Vec3& origin = {0, 0, 0});

// A UV sphere of radius r about `centre`: poles on z, `rings` bands of
// `segments` quads (two triangles each; fans at the poles), wound outwards.
SceneObject uvSphere(int rings, int segments, double r, const Vec3& centre = {0, 0, 0});

// The object's vertices and triangles as an OBJ file.
void writeObj(const std::string& path, const SceneObject& o);

}  // namespace darkroom::test
