#pragma once
// The index a batch writes (`run --foreach --index FILE`): a CSV of the
// entries shaded, their parameters and the files written for each, the same
// whatever the number of processes or entries in flight.
#include "batch_plan.h"

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace darkroom::workflows::batch {

// The index's file columns: one per output path of the per-entry sinks and
// one per database a row-fed sink writes; FILE alone, or FILE_<node>[_<port>].
std::vector<std::string> indexColumns(const std::vector<OutputPort>& outputs,
                                      const std::vector<DatabaseSink>& databases);

// The index: the database's parameter columns, then the file columns, one
// row per entry in database order, file names relative to the index's folder.
void writeIndex(const std::string& path, const CinemaDatabase& db, const std::vector<std::string>& fileColumns,
                const std::map<std::size_t, std::vector<std::string>>& filesByRow);

// The index of plan `p` at `path`: the entries a resume kept and those shaded
// now, by any process. `todo`: the positions in p.rows that were to be
// shaded; `shadedRecords`: each process's positions shaded, one per line.
void writeIndexOf(const std::string& path, const Plan& p, const std::vector<std::size_t>& todo,
                  const std::vector<std::string>& shadedRecords);

}  // namespace darkroom::workflows::batch
