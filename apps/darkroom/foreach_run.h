#pragma once
// `darkroom run PIPELINE --foreach NODE`: the pipeline once per entry of the
// Cinema database that NODE (a CinemaReader) reads, output paths renamed per
// entry. Under mpirun the entries are shared among the ranks (entry_scheduler.h)
// and rank 0 alone draws the progress bar. --resume skips entries whose
// outputs all exist (every output is written atomically, so an existing file
// is a whole one) and that the databases row-fed sinks write in mode resume
// hold; --index writes a CSV of the entries shaded and the files written for
// each, the same whatever the number of ranks. Those databases are staged per
// rank and merged by rank 0 (database_sinks.h).
#include "progress_bar.h"

#include <darkroom/core/evaluator.h>

#include <functional>
#include <string>

namespace darkroom::cli {

struct ForeachSettings {
    std::string node;   // the CinemaReader
    std::string where;  // optional selection of entries
    std::string index;  // optional CSV of the entries and their files
    bool resume = false;
    bool quiet = false;  // no summary of how the entries were shared
};

// Returns the exit code. `evaluate(title, sinks)` runs the graph once for
// those sinks (and prints its profile when asked). Sinks that depend on the
// reader run once per entry; the others (e.g. a Movie of the database a
// CinemaWriter fills) once after the last entry, on rank 0.
int runForeach(Graph& graph, Evaluator& evaluator, EvaluatorOptions& options, ProgressBar& bar,
               const ForeachSettings& settings,
               const std::function<void(const std::string&, std::vector<std::string>)>& evaluate);

}  // namespace darkroom::cli
