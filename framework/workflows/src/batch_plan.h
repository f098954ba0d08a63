#pragma once
// What a batch shades and writes, worked out before any entry is shaded and
// the same on every process: the database read and the selected entries, the
// sinks per entry and after the last, the output paths renamed per entry and
// the databases row-fed sinks fill (batch.cpp). Every refusal that needs no
// file system state is made here.
#include "batch_paths.h"

#include <darkroom/core/evaluator.h>
#include <darkroom/data/cinema/database.h>
#include <darkroom/workflows/batch.h>
#include <darkroom/workflows/written_databases.h>

#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace darkroom::workflows::batch {

struct Plan {
    std::filesystem::path source;  // the database read
    std::optional<CinemaDatabase> db;
    std::vector<std::size_t> rows;  // the selected entries' rows, in database order (batch_entries.h)
    // Each entry's file-name-safe name, for the output paths renamed per
    // entry. A database sink (CinemaWriter) names its entries from the row
    // it is fed, so its files go by CinemaDatabase::entryName.
    std::map<std::size_t, std::string> names;
    std::vector<std::string> entrySinks, finalSinks;
    std::vector<OutputPort> outputs;
    std::vector<DatabaseSink> databases;
    // Edges from a database sink into a sink run after the last entry, and
    // the database's final path: after the last entry the edge is replaced by
    // that path, so the reader of the database (Movie) does not pull the
    // per-entry graph again.
    std::vector<std::pair<Edge, std::string>> afterLast;
    // Databases are written through staging databases, one per writer (a
    // process, or an entry in flight in one): batch_staging.h.
    bool staging = false;
    // Staging in a lone process: its first lane writes the databases in
    // place, in their nodes' modes, and the merge adds the other lanes'
    // entries to them (kept, as a resume keeps them).
    bool firstLaneInPlace = false;
    EvaluatorOptions options;

    const std::string& entryName(std::size_t row) const { return names.at(row); }

    // The files entry `row` writes through the renamed output paths.
    std::vector<std::string> filesOf(std::size_t row) const;
};

// The plan of `settings` over `g`, shaded by `processes` processes of
// `lanes` lanes each (batch_lanes.h): with more than one writer in all, each
// database is written through staging databases.
// Throws InputError for what is refused before any shading: no such reader,
// a database that cannot be opened, an empty selection, a node reading what
// is written entry by entry, a database written over the one read, two
// entries writing one file.
Plan planBatch(const Graph& g, const BatchSettings& settings, EvaluatorOptions options, int processes, int lanes);

}  // namespace darkroom::workflows::batch
