#pragma once
// Point lists from any file: the CSV form (darkroom/data/formats/point_list.h)
// or the vertices of a mesh file.
#include <darkroom/data/formats/point_list.h>
#include <darkroom/export.h>

#include <string>

namespace darkroom {

// Reads a .csv as readPointListCsv does, or the vertices of every part of any
// file readMesh reads (.ply, .obj, .off, .stl, .vtk, .vtp, .vtu) with their point fields
// (radius NaN). Throws darkroom::Error naming file:line and what was expected.
DARKROOM_API PointList readPointList(const std::string& path);

}  // namespace darkroom
