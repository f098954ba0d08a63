#pragma once
// What the processes loading one scene must agree on, through
// ProcessGroup::allGather: which parts a parallel file has and their fields,
// the scene's bounds, and where each process's primitives start.
#include <darkroom/scene/scene_partition.h>
#include <darkroom/scene.h>

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace darkroom::partition {

inline constexpr float kNaNFloat = std::numeric_limits<float>::quiet_NaN();

// Agrees on the parts of one parallel file: every process gets one part per
// representation any process read (surface, lines, points in that order),
// empty (no vertices, the agreed fields with no values) where it read none.
// `error` is this process's failure, if any: then every process throws the
// first one, prefixed with its rank when there are several processes. Without
// a group: throws `error` or returns `local` in that order.
std::vector<SceneObject> agreeParts(std::vector<SceneObject> local, ProcessGroup* group, const std::string& error,
                                    const std::string& source);

// The union of every process's bounds.
Bounds agreeBounds(const Bounds& local, ProcessGroup& group);

// For each entry of `counts` (the same length on every process): the sum of
// the counts of the lower ranks (the exclusive prefix sum) and, in `totals`,
// the sum over all ranks.
std::vector<std::uint64_t> exclusiveSums(const std::vector<std::uint64_t>& counts, ProcessGroup& group,
                                         std::vector<std::uint64_t>& totals);

// Throws the first of the processes' errors, the same on every process.
// `error` is this process's ("" = none). Collective.
void agreeNoError(const std::string& error, ProcessGroup& group);

}  // namespace darkroom::partition
