#pragma once
// The databases' side of a batch: before any entry, each database checked
// against its writer's mode, its staging folder prepared and what a resume
// keeps decided; after the last, the staged entries adopted into the
// database (written_databases.h) and the index written.
#include "batch_plan.h"

#include <darkroom/core/process_group.h>
#include <darkroom/workflows/batch.h>

#include <cstddef>
#include <exception>
#include <string>
#include <vector>

namespace darkroom::workflows::batch {

// The positions in p.rows still to shade, the same on every process: the
// lead checks the databases against their writers' modes (a refusal, thrown
// as InputError on every process, stops the run before any shading) and
// decides what a resume keeps.
std::vector<std::size_t> entriesToShade(const BatchSettings& s, const Plan& p, ProcessGroup& group);

// On the lead, after every process has finished: the staged entries merged
// (also after a failure, so the database holds what was shaded and a resume
// completes it), and the index. `shadedRecords`: each process's positions
// shaded, one per line. The first failure is kept in `failure`.
void finishOnLead(const BatchSettings& s, const Plan& p, const std::vector<std::size_t>& todo,
                  const std::vector<std::string>& shadedRecords, std::exception_ptr& failure);

}  // namespace darkroom::workflows::batch
