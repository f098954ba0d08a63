#pragma once
// The paths a batch writes per entry: output paths renamed per entry, and
// where the evaluator puts a relative one.
#include <darkroom/core/evaluator.h>
#include <darkroom/data/cinema/database.h>

#include <cstddef>
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

}  // namespace darkroom::workflows::batch
