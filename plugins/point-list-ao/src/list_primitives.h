#pragma once
// A point list as occluders: each point a sphere, except that points of a
// list with a `line` column whose consecutive rows share a line value are
// joined into round lines (the segments between them, radius interpolated),
// which is how a capture stores streamlines (docs/scene-format.md).
#include "primitive_grid.h"

#include <darkroom/camera.h>
#include <darkroom/data/formats/point_list.h>

#include <string>

namespace darkroom::listao {

// The column that groups points into lines.
inline const std::string kLineColumn = "line";

// Positions relative to the camera's eye in its view frame (ViewGeometry's);
// radius: the list's, or `fallbackRadius` where it gives none, times `scale`.
Primitives listPrimitives(const PointList& list, const Camera& camera, double fallbackRadius, double scale);

}  // namespace darkroom::listao
