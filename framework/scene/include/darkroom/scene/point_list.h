#pragma once
// Point lists from any file: the CSV form (darkroom/data/formats/point_list.h)
// or the vertices of a mesh file.
#include <darkroom/data/formats/point_list.h>
#include <darkroom/context.h>
#include <darkroom/data/cinema/row.h>
#include <darkroom/export.h>

#include <functional>
#include <string>

namespace darkroom {

// Reads a .csv as readPointListCsv does, or the vertices of every part of any
// file readMesh reads (.ply, .obj, .off, .stl, .vtk, .vtp, .vtu) with their point fields
// (radius NaN). Throws darkroom::Error naming file:line and what was expected.
DARKROOM_API PointList readPointList(const std::string& path);

// The point list a node's `points` parameter names (Spheres, PointListAO):
// {column} placeholders filled from the Cinema row `row()` returns (asked
// only when there are placeholders), the path resolved against the
// pipeline's folder and recorded as read, the list's warnings passed to the
// context. Throws darkroom::Error for an empty `spec`, placeholders without a
// row, or an unreadable list. `resolved`, when given, gets the file's path.
DARKROOM_API PointList readNodePointList(Context& ctx, std::string spec, const std::function<const Row&()>& row,
                                         std::string* resolved = nullptr);

}  // namespace darkroom
