#pragma once
// The scene file's side of smooth normals: while objects are loaded, the
// vertex normals each surface part brought (an isosurface's gradient, a
// file's own normals) are held aside, so that the objects' `fields:` lists
// and the default scalar channels never see them; once every object is
// loaded they are attached, and surfaces without any get averaged ones.
#include <darkroom/scene/vertex_normals.h>

#include <vector>

namespace darkroom::scenefile {

// The normals `part` carries as N.x, N.y, N.z (removed from its fields), or
// else those its file brought (nx, ny, nz or Normals; left in place as
// ordinary fields); empty if neither.
VertexNormals takeShadingNormals(SceneObject& part);

// Per surface object: attaches `held[i]` when there is one, else averages
// (averageVertexNormals at `featureAngle` degrees). `held` runs parallel to
// scene.objects; lines and points are left as they are.
void attachShadingNormals(Scene& scene, std::vector<VertexNormals>& held, double featureAngle);

}  // namespace darkroom::scenefile
