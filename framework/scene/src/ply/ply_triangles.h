#pragma once
// The direct reader of binary PLY triangle meshes, the usual form of big
// scanned and simulated surfaces: the file is read a window at a time
// straight into the arrays the ray tracer shares (SceneObject's vertices,
// indices and fields), each window decoded in parallel, with no copy of the
// file in memory and no intermediate mesh (docs/performance.md, "Capture ingest").
#include <darkroom/scene.h>

#include <cstddef>
#include <optional>
#include <string>

namespace darkroom::ply {

// Reads `path` if it is a binary PLY whose faces are all triangles (a
// 'vertex_indices' list of 3 integers), whose vertices have no list, and
// whose other elements are fixed-size records: the one surface object the
// general reader (ply_reader.cpp) would make of it, value for value, named
// `name`. Returns nothing for any other file, and for one whose body is wrong
// in any way (a face that is not a triangle, an index out of range, a body
// shorter than its header says), so that the general reader reads it and
// says what is wrong. Throws the general reader's errors about the header.
std::optional<SceneObject> readTriangles(const std::string& path, const std::string& name, std::size_t windowBytes);

}  // namespace darkroom::ply
