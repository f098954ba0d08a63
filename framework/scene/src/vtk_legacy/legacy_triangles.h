#pragma once
// The direct reader of binary legacy VTK triangle meshes: the file is read a
// window at a time straight into the arrays the ray tracer shares
// (SceneObject's vertices, indices and point fields), each window decoded in
// parallel, with no copy of the file in memory and no intermediate mesh
// (docs/performance.md, "Capture ingest"); as ply/ply_triangles.h for PLY.
#include <darkroom/scene.h>

#include <cstddef>
#include <optional>
#include <string>

namespace darkroom::vtk_legacy {

// Reads `path` if it is a BINARY POLYDATA of triangles as legacy_layout.h
// describes: the one surface object the general reader
// (vtk_legacy_reader.cpp) would make of it, value for value, named `name`.
// Returns nothing for any other file, and for one whose cells are wrong in
// any way (a cell that is not a triangle, an index out of range), so that
// the general reader reads it or says what is wrong. Throws InputError when
// an array it would allocate exceeds --max-decoded-bytes.
std::optional<SceneObject> readTriangles(const std::string& path, const std::string& name, std::size_t windowBytes);

}  // namespace darkroom::vtk_legacy
