#pragma once
// The Cinema databases that sinks fed the reader's row (CinemaWriter) fill
// during `darkroom run --foreach`. Under mpirun no two ranks may write one
// database (the writer locks it), so each rank writes its entries into a
// staging database of its own, <database>.staging/rank-<k>, and rank 0 adopts
// them all into the database when every rank has finished; the result is the
// database one process writes, byte for byte (docs/scale-out.md, "Batch
// shading"). The staging folder lies beside the database, so its products
// are renamed, not copied, into place.
#include <darkroom/export.h>
#include <darkroom/core/evaluator.h>

#include <set>
#include <string>
#include <vector>

namespace darkroom::workflows {

struct DatabaseSink {
    std::string node;
    std::string type;
    std::string port;      // its output-path input, which names the database
    std::string database;  // resolved as the node resolves it
    std::string mode;      // the node's: create, overwrite or resume
    std::string format;    // the node's product format (png, exr), when it has one
    std::string pipeline;  // what the node records as its upstream pipeline (pipeline_record.h), when it does
};

// The sinks among `sinks` with a connected Row input and an output-path
// input (PortType::OutputPath), the database they write. One whose database comes through an edge is left to itself
// alone, and refused (Error) over ranks, where it could not be staged.
DARKROOM_API std::vector<DatabaseSink> databaseSinks(const Graph& graph, const std::vector<std::string>& sinks,
                                        const EvaluatorOptions& options, bool overRanks);

DARKROOM_API std::string stagingFolder(const DatabaseSink& sink);
DARKROOM_API std::string stagingDatabase(const DatabaseSink& sink, int rank);

// "node 'store' (CinemaWriter)", to begin messages with.
DARKROOM_API std::string label(const DatabaseSink& sink);

// Before the entries, by one process: throws Error, as the writer would at
// its first entry, when the database does not suit the node's mode (create:
// it exists and is not empty); settles what an interrupted run over ranks
// left staged: create refuses it, overwrite removes it, resume adopts it now.
// A staging database that another run is writing is refused, and so is a
// <database>.staging that Darkroom did not make (no marker inside): it is
// never read nor removed. `overRanks`: makes the staging folder, marked.
DARKROOM_API void prepareDatabase(const DatabaseSink& sink, bool overRanks);

// After every rank has finished, by one process: adopts every staged entry
// into the database, opened in the node's mode (resume keeps the entries it
// has), and removes the staging folder. Nothing staged: nothing changes.
// `keepWritten`: the database was written in this run (by the first lane of
// a lone process, batch_lanes.h) and is opened as a resume, keeping its
// entries. Throws Error; what it could not adopt stays staged for a resume.
DARKROOM_API void mergeStagedEntries(const DatabaseSink& sink, bool keepWritten = false);

// The entries (file names without extension, as CinemaDatabase::entryName
// gives them) that the database holds complete, in the node's format, and a
// resume keeps; empty unless the mode is resume.
DARKROOM_API std::set<std::string> entriesKeptByResume(const DatabaseSink& sink);

}  // namespace darkroom::workflows
