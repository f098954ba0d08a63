#pragma once
// Parallel VTK XML files (.pvtp, .pvtu): a small XML file naming one piece
// file per <Piece Source="...">. Read whole (readParallelVtk, what readMesh
// does) or only some pieces, with the parts agreed over a ProcessGroup.
#include <darkroom/scene/scene_partition.h>
#include <darkroom/scene.h>

#include <string>
#include <vector>

namespace darkroom::partition {

// True for .pvtp / .pvtu (case-insensitive).
bool isParallelVtk(const std::string& path);

// The piece files, resolved against the parallel file's folder. Throws
// darkroom::Error naming the file and line (not a parallel VTK file, no
// pieces, ghost levels, which would draw the ghost cells twice).
std::vector<std::string> parallelVtkPieces(const std::string& path);

// Reads the pieces (all of them, or with a group the block blockOf() gives
// this process) and appends each part to the part of the same
// representation, in piece order, so primitive ids run piece after piece.
// A group also makes every process agree on the parts (the union of what any
// piece has, empty where this process has none) and on their fields. Parts
// are named `<stem>` or `<stem>/<representation>` from that union. Collective
// over `group` when given; errors are agreed (see scene_partition.h).
std::vector<SceneObject> readParallelVtkPieces(const std::string& path, ProcessGroup* group,
                                               std::vector<std::string>* warnings);

// Appends `piece` to `into` (same representation and fields): vertices,
// re-based indices, cell map and fields. Throws darkroom::Error naming
// `source` when the fields differ.
void appendPart(SceneObject& into, const SceneObject& piece, const std::string& source);

}  // namespace darkroom::partition
