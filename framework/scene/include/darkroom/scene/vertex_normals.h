#pragma once
// Shading normals of surfaces: one unit normal per vertex, which a capture
// interpolates across each triangle instead of storing the triangle's own
// (flat) normal, so that lighting shows the surface the mesh approximates
// rather than its facets (docs/scene-format.md, "Normals").
//
// A surface object carries them as three point fields named after the
// G-buffer channels they become, N.x, N.y and N.z. Those names are never
// scalar channels (the capture refuses them as such), so the convention
// needs no change to SceneObject, which is part of the SDK's ABI; the
// capture backend takes such fields as normals (plugins/capture-embree).
#include <darkroom/export.h>
#include <darkroom/math.h>
#include <darkroom/scene.h>

#include <vector>

namespace darkroom {

// x, y, z: the point fields that hold a surface's vertex normals.
inline constexpr const char* kVertexNormalFields[3] = {"N.x", "N.y", "N.z"};

// Normals as x, y, z per vertex. A zero normal means "none here": the
// capture then falls back to the triangle's own normal where it needs it.
using VertexNormals = std::vector<float>;

// Replaces o's vertex normals (x, y, z per vertex) with `normals`.
DARKROOM_API void setVertexNormals(SceneObject& o, const VertexNormals& normals);

// Removes o's vertex normals and returns them; empty if it has none.
DARKROOM_API VertexNormals takeVertexNormals(SceneObject& o);

// The normals a mesh file brought along, as the readers keep them: PLY's
// vertex properties nx, ny, nz, or a three-component point array named
// Normals (VTK's convention; the fields Normals_0, _1, _2), normalised;
// empty if the object has neither.
DARKROOM_API VertexNormals fileVertexNormals(const SceneObject& o);

// The normals of a surface scaled by `scale` about the origin (positions
// p -> scale * p): gradients transform by the inverse scale, then normalise.
DARKROOM_API void scaleVertexNormals(VertexNormals& normals, const Vec3& scale);

// ParaView's Generate Surface Normals: each vertex gets the average of the
// normals of the triangles around it, weighted by each triangle's angle at
// the vertex, but not across an edge whose two triangles' normals differ by
// more than `featureAngleDegrees`: such a vertex is split into one vertex per
// side (a copy with the same position and point fields), so a cube keeps
// flat faces and sharp edges. Normals follow each triangle's winding
// ((v1 - v0) x (v2 - v0)). Triangles of zero area take no part. Surfaces
// only (lines and points are left as they are); replaces any normals o has.
// Deterministic: the result does not depend on the number of threads.
DARKROOM_API void averageVertexNormals(SceneObject& o, double featureAngleDegrees);

}  // namespace darkroom
