#pragma once
// The steps a distributed capture takes after each rank has ray traced its
// part for one camera, shared by the runner (`mpirun darkroom capture`) and
// the in situ library: make the ids global, composite by depth, drop the id
// channels that were rendered only to break ties, and agree on errors.
#include <darkroom/buffer.h>
#include <darkroom/mpi/depth_compositing.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace darkroom::mpi {

// `local` must carry "objectId" and "primitiveId" (local primitive ids;
// `primitiveOffsets[object]` is where this rank's share of each object starts
// in the whole object). Returns the composite on the root, nullptr elsewhere
// (collective). `keepObjectId` / `keepPrimitiveId`: whether the caller asked
// for those channels; the others are removed from the result.
std::shared_ptr<WritableBuffer> compositeCapture(const Communicator& comm, const Buffer& local,
                                                 const std::vector<std::uint64_t>& primitiveOffsets,
                                                 bool keepObjectId, bool keepPrimitiveId,
                                                 CompositeStats* stats = nullptr);

// The first non-empty message among all ranks' `mine` ("rank k: ..."
// unless every rank reports the same), or "" when none failed. Collective.
std::string agreedError(const Communicator& comm, const std::string& mine);

// For each entry of `counts` (the same length on every rank), the sum over
// lower ranks (collective).
std::vector<std::uint64_t> exclusiveSums(const Communicator& comm, const std::vector<std::uint64_t>& counts);

}  // namespace darkroom::mpi
