#pragma once
// Batch shading: a pipeline evaluated once per entry of the Cinema database
// its reader reads — `darkroom run PIPELINE --foreach NODE`, alone or under
// mpirun, and any other front end (the coming Python module) — in one place
// (docs/publishing.md, docs/scale-out.md "Batch shading").
//
// Sinks that depend on the reader run once per entry, their output paths
// renamed per entry (out.png -> out_<entry>.png, or {entry} replaced), except
// sinks fed the reader's row (CinemaWriter), which name entries themselves;
// the other sinks run once, after the last entry, on the lead: those no entry
// reaches and those that read what a per-entry sink wrote (a Movie connected
// to CinemaWriter's `written`, which then reads the finished database: the
// batch replaces that edge by the database's path). Every edit the batch
// makes to `graph` (the reader's entry, staging paths, that edge) is
// undone when it returns: the caller keeps the pipeline it had. Over several processes the entries are
// handed out by the group's work queue, each process writes the databases
// into staging databases of its own and the lead merges them
// (written_databases.h). The entries a process shades are one sequence of
// its evaluator (Evaluator::beginSequence): a CinemaWriter holds its database
// across them and lets it go at the end, before the merge. A resume skips entries whose outputs all exist and
// that every database written in mode resume holds. In one process several
// entries are in flight at once (BatchSettings::inFlight, batch_lanes.h):
// each lane shades whole entries with a copy of the graph and an evaluator
// of its own, and writes its databases through a staging database of its
// own, merged as over ranks; the outputs are those of one entry at a time,
// byte for byte. The index (a CSV of the
// entries and the files written for each) is the same whatever the number of
// processes.
#include <darkroom/export.h>
#include <darkroom/core/evaluator.h>
#include <darkroom/core/process_group.h>

#include <exception>
#include <functional>
#include <string>
#include <vector>

namespace darkroom::workflows {

struct BatchSettings {
    std::string reader;  // the entry reader (CinemaReader), whose `entry` the batch sets (entry_ports.h)
    std::string where;   // the entries to shade (--where syntax); empty: all
    std::string index;   // the index CSV to write; empty: none
    bool resume = false;
    // Entries shaded at once in this process, each with its own copy of the
    // graph and evaluator (reading the next while shading and writing the
    // previous ones); memory grows with it. 0: automatic (3). Under several
    // processes each takes one at a time: the ranks overlap one another.
    int inFlight = 0;
};

struct BatchCallbacks {
    // Runs `graph` with `evaluator` once for `sinks` ("entry phi=30 (2 of
    // 12)", "after the last entry": the title, for profiles). Default:
    // Evaluator::run. With entries in flight, called from several threads
    // at once, each with its own evaluator and graph: what it prints or
    // records must take a lock.
    std::function<void(Evaluator& evaluator, const Graph& graph, const std::string& title,
                       const std::vector<std::string>& sinks)>
        evaluate;
    // On the lead: the fraction of all entries done (every process's) and
    // the entry. Called one at a time, from any thread.
    std::function<void(double, const std::string&)> progress;
};

struct BatchSummary {
    std::size_t selected = 0;  // entries the selection gave
    std::size_t kept = 0;      // entries a resume kept
    int inFlight = 1;          // entries this process had in flight at once
    // On the lead: entries shaded now, per process in rank order.
    std::vector<std::size_t> shadedPerProcess;
    // What failed on this process: an entry ("entry phi=30: ..."), a graph
    // error (GraphError), the merge, the index or a sink after the last
    // entry. The databases then hold what was shaded; a resume completes them.
    std::exception_ptr failure;
    // Another process failed (and reports it).
    bool failedElsewhere = false;
};

// Collective over `group`. Throws InputError, the same on every process,
// for what is refused before any shading: no such reader, a database that
// cannot be opened, an empty selection, two entries writing one file, a
// database written over the one read, a database that does not suit its
// writer's mode, a resume of another pipeline. Throws Cancelled when the
// evaluation is cancelled. `options` is the evaluator's; its progress
// callback is replaced per entry.
DARKROOM_API BatchSummary shadeEntries(Graph& graph, Evaluator& evaluator, EvaluatorOptions options,
                                       const BatchSettings& settings, ProcessGroup& group,
                                       const BatchCallbacks& callbacks);

}  // namespace darkroom::workflows
