#pragma once
// The entries one process shades, several in flight at once (`run --foreach
// --in-flight N`): each lane shades whole entries, one after another, with a
// copy of the pipeline and an evaluator of its own, taking the next entry
// from the process's work queue when it finishes one. While one lane reads
// its entry's products, another shades and a third encodes and writes, so
// reading, shading and writing overlap without any node knowing. Memory is
// bounded by the lanes: each holds one entry in flight and a share of the
// evaluator cache. A lane's database sinks (CinemaWriter) write into a
// staging database of its own, adopted by the lead at the end as under
// mpirun (written_databases.h), so the outputs, data.csv and the index are
// those of one lane, byte for byte (docs/scale-out.md, "Batch shading").
#include "batch_plan.h"

#include <darkroom/core/evaluator.h>
#include <darkroom/core/process_group.h>
#include <darkroom/workflows/batch.h>

#include <algorithm>
#include <cstddef>
#include <exception>
#include <string>
#include <vector>

namespace darkroom::workflows::batch {

// The lanes this process runs for `settings` over `g`: 1 under several
// processes (the ranks already overlap one another) and when a row-fed
// writer's database comes through an edge (it could not be staged per lane);
// else settings.inFlight, or automatically kAutomaticLanes.
inline constexpr int kAutomaticLanes = 3;
int lanesFor(const Graph& g, const BatchSettings& settings, const ProcessGroup& group);

// The lanes that have entries to shade: `lanes`, no more than `entries`, at least 1.
inline int lanesInFlight(int lanes, std::size_t entries) {
    return entries < std::size_t(lanes) ? std::max(1, int(entries)) : lanes;
}

// The staging database a writer of `group`'s process writes through lane `lane` of `lanes`.
int writerIndex(const ProcessGroup& group, int lane, int lanes);

// Shades this process's share of the positions `todo` of p.rows over
// `lanes` lanes (no more than the entries: lanesInFlight): lane 0 with `evaluator`, the others with evaluators of
// their own, each with its own copy of `graph` (the batch's common edits
// made). Each lane's entries are one sequence of its evaluator: a
// CinemaWriter holds its database across them and lets it go as the lane
// ends, before the lead merges. Returns the positions shaded, one per line.
// An entry that fails stops every lane from taking more (`failure`, the
// first); throws Cancelled when an evaluation was cancelled, after every
// lane has stopped.
std::string shadeOverLanes(const Graph& graph, Evaluator& evaluator, const BatchSettings& settings, const Plan& p,
                           const std::vector<std::size_t>& todo, ProcessGroup& group, const BatchCallbacks& cb,
                           int lanes, std::exception_ptr& failure);

}  // namespace darkroom::workflows::batch
