#pragma once
// What a batch writes, worked out before any entry is shaded: the sinks per
// entry and after the last, the output paths renamed per entry, and the
// index of the entries and their files (batch.cpp).
#include <darkroom/core/evaluator.h>
#include <darkroom/data/cinema/database.h>
#include <darkroom/workflows/written_databases.h>

#include <cstddef>
#include <map>
#include <set>
#include <optional>
#include <string>
#include <vector>

namespace darkroom::workflows::batch {

// The output path of entry `row`, named `entry` (batch_entries.h):
// out.png -> out_phi=30_theta=45.png, or, when the path holds placeholders,
// {entry} replaced by that name and
// {column} by the row's cell in that column of the database ("frames/{time}.png"),
// made safe for file names as entry names are. A placeholder naming no
// column throws darkroom::InputError naming the path and listing the columns.
std::string perEntryPath(const std::string& path, const std::string& entry, const CinemaDatabase& db,
                         std::size_t row);

// A Path input of a per-entry sink, renamed per entry.
struct OutputPort {
    std::string node, port, original;
};

// The Path parameters of the output nodes that run per entry, to rename per
// entry. A sink fed the entry's row (a Row input connected, as CinemaWriter
// has) names its entries itself: its paths stay as given.
std::vector<OutputPort> outputPorts(const Graph& g, const std::vector<std::string>& sinks);

// A node's parameter, or its port's default.
std::string currentValue(const Graph& g, const std::string& node, const std::string& port);

// Where the evaluator writes a relative output path (HostContext::resolveOutputPath).
std::string resolvedOutput(const EvaluatorOptions& o, const std::string& path);

// The index's file columns: one per output path of the per-entry sinks and
// one per database a row-fed sink writes; FILE alone, or FILE_<node>[_<port>].
std::vector<std::string> indexColumns(const std::vector<OutputPort>& outputs,
                                      const std::vector<DatabaseSink>& databases);

// The index: the database's parameter columns, then the file columns, one
// row per entry in database order, file names relative to the index's folder.
void writeIndex(const std::string& path, const CinemaDatabase& db, const std::vector<std::string>& fileColumns,
                const std::map<std::size_t, std::vector<std::string>>& filesByRow);

// The batch's edits of the caller's graph (an entry's parameters, staging
// paths, an edge replaced after the last entry), undone when it goes out of
// scope: a long-lived front end (the editor, a notebook) keeps the pipeline
// it had, and only the evaluator's cache remembers the batch.
class GraphEdits {
public:
    explicit GraphEdits(Graph& g) : g_(g) {}
    ~GraphEdits();
    GraphEdits(const GraphEdits&) = delete;
    GraphEdits& operator=(const GraphEdits&) = delete;
    const Graph& graph() const { return g_; }
    void set(const std::string& node, const std::string& port, Value value);
    void disconnect(const Edge& e);

private:
    struct Saved {
        std::string node, port;
        std::optional<Value> value;  // unset: the port's default
    };
    Graph& g_;
    std::vector<Saved> parameters_;
    std::vector<Edge> edges_;
};

}  // namespace darkroom::workflows::batch
