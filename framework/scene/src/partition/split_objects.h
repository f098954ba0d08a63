#pragma once
// Cutting a whole object into per-process shares of its primitives.
#include <darkroom/scene.h>

#include <cstdint>
#include <utility>

namespace darkroom::partition {

// The primitive range [first, last) that process `rank` of `size` keeps:
// balanced by count, cut only where a cut changes nothing the ray tracer
// computes (never inside a connected run of line segments).
std::pair<std::size_t, std::size_t> shareOf(const SceneObject& object, int rank, int size);

// The object restricted to primitives [first, last), with the same ids for
// everything the G-buffer reads: triangles and segments keep the whole
// vertex array and fields (only their indices are cut); points keep their
// slice of vertices and point fields. Cell fields stay whole, reached through
// an explicit primitive -> cell map.
SceneObject shareObject(const SceneObject& object, std::size_t first, std::size_t last);

// The number of cells an object's cell fields index (its cell-field length,
// or what its primitive -> cell map reaches).
std::size_t cellCountOf(const SceneObject& object);

}  // namespace darkroom::partition
