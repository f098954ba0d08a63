#pragma once
// Loading a capture scene over several processes, each holding only its part
// (docs/scale-out.md, "Distributed capture").
//
// Every process gets the objects of the whole scene in the same order, each
// holding this process's share of the object's primitives, plus the offset
// of that share within the whole object, so that ids rendered locally become
// the ids of the single-process capture (primitive id = offset + local id).
// Cameras, channels and default radii are those of the whole scene: they are
// computed from bounds agreed between the processes.
//
// Where the shares come from:
// - a parallel VTK file (.pvtp, or .pvtu of 2D cells): process r of P reads
//   only pieces [r N / P, (r + 1) N / P) of the N pieces;
// - anything else (one mesh file, a generator, a volume representation):
//   every process loads it and keeps a contiguous range of its primitives,
//   balanced by primitive count. Line segments are cut only where a polyline
//   ends, since Embree caps a tube differently where it has no neighbour.
//
// The framework knows nothing of MPI: the processes talk through ProcessGroup
// (darkroom/core/process_group.h; the runner's is MPI_Allgatherv). Errors are agreed too: a problem on one
// process (a piece it cannot read) makes every process throw the same
// darkroom::Error, so none is left waiting in a collective.
#include <darkroom/export.h>
#include <darkroom/core/process_group.h>
#include <darkroom/scene/scene_file.h>

#include <cstdint>
#include <string>
#include <vector>

namespace darkroom {

struct PartitionedScene {
    // The whole scene's objects (same count, order, names, representations
    // and fields on every process), each with this process's share of the
    // primitives; cameras, request and backend as for the whole scene.
    SceneDescription description;
    // Per object: the primitive id, in the whole object, of this share's first primitive.
    std::vector<std::uint64_t> primitiveOffset;
    // Per object: primitives of the whole object (the sum of all shares).
    std::vector<std::uint64_t> wholePrimitiveCount;
};

// Collective over `group`. Throws darkroom::Error (the same on every process)
// as loadSceneFile does, or naming the process whose part failed.
DARKROOM_API PartitionedScene loadSceneFilePart(const std::string& path, ProcessGroup& group,
                                                const SceneLoadOptions& options = {});
DARKROOM_API PartitionedScene parseSceneFilePart(const std::string& yamlText, const std::string& sourceName,
                                                 const std::string& baseDir, ProcessGroup& group,
                                                 const SceneLoadOptions& options = {});

// The contiguous block [first, last) of `count` items that process `rank` of
// `size` takes: first = rank * count / size.
DARKROOM_API std::pair<std::size_t, std::size_t> blockOf(std::size_t count, int rank, int size);

}  // namespace darkroom
