#pragma once
// How a scene-file object is drawn: the representation it asks for, the
// radius of its tubes and spheres, its transform and the fields it keeps.
#include <darkroom/scene.h>

#include <string>
#include <vector>

namespace darkroom::scenefile {

// Surface keeps each part as read (triangles, lines, vertices). Lines turns
// triangles into their unique edges (a wireframe of tubes). Points turns every
// vertex into a sphere; cell fields, which no longer map to a primitive, are dropped.
SceneObject restyle(SceneObject o, Representation wanted);

// Sets the radius of every vertex (lines and points are drawn with it).
void setRadius(SceneObject& o, float radius);

// Scales about the origin, then translates; radii scale with the mean |scale|.
void transform(SceneObject& o, const Vec3& scale, const Vec3& translate);

// Keeps only the named fields (in that order); names an object lacks are skipped.
void keepFields(SceneObject& o, const std::vector<std::string>& names);

}  // namespace darkroom::scenefile
