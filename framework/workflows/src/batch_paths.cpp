#include "batch_paths.h"

#include "entry_ports.h"

#include <darkroom/error.h>
#include <darkroom/data/cinema/naming.h>

#include <algorithm>
#include <filesystem>

namespace darkroom::workflows::batch {

namespace fs = std::filesystem;

namespace {

// The text a placeholder stands for, safe in a file name: the entry's name,
// or a cell of its row.
std::string placeholderValue(const std::string& path, const std::string& name, const std::string& entry,
                             const CinemaDatabase& db, std::size_t row, bool startsName) {
    if (name == "entry") return entry;
    if (const auto column = db.findColumn(name)) return cinemaNamePart(db.cell(row, *column), startsName);
    std::string columns;
    for (const auto& c : db.columns()) columns += (columns.empty() ? "" : ", ") + c.name;
    throw InputError("the output path " + path + " names {" + name + "}, which is neither {entry} nor a column of " +
                     db.path() + " (its columns: " + columns + ")");
}

}  // namespace

std::string perEntryPath(const std::string& path, const std::string& entry, const CinemaDatabase& db,
                         std::size_t row) {
    std::string out;
    bool placeholders = false;
    for (std::size_t i = 0; i < path.size();) {
        const std::size_t close = path[i] == '{' ? path.find_first_of("{}/", i + 1) : std::string::npos;
        if (close == std::string::npos || path[close] != '}' || close == i + 1) {
            out += path[i++];
            continue;
        }
        const bool startsName = out.empty() || out.back() == '/';
        out += placeholderValue(path, path.substr(i + 1, close - i - 1), entry, db, row, startsName);
        placeholders = true;
        i = close + 1;
    }
    if (placeholders) return out;
    const fs::path p(path);
    return (p.parent_path() / (p.stem().string() + "_" + entry + p.extension().string())).string();
}

// The output paths (PortType::OutputPath) of the sinks that run per entry,
// to rename per entry. A sink fed the entry's row (a Row input connected, as
// CinemaWriter has) names its entries itself: its paths stay as given.
std::vector<OutputPort> outputPorts(const Graph& g, const std::vector<std::string>& sinks) {
    std::vector<OutputPort> out;
    for (const auto& name : sinks) {
        const Node* n = g.node(name);
        if (isFedARow(g, *n)) continue;
        for (const auto& p : g.ports(*n).inputs) {
            if (p.type != PortType::OutputPath) continue;
            const Value* v = n->parameter(p.name);
            const std::string original = v ? v->asString() : p.defaultValue.asString();
            if (!original.empty()) out.push_back({name, p.name, original});
        }
    }
    return out;
}

std::string currentValue(const Graph& g, const std::string& node, const std::string& port) {
    const Node* n = g.node(node);
    if (const Value* v = n->parameter(port)) return v->asString();
    return g.ports(*n).input(port)->defaultValue.asString();
}

// Where the evaluator writes a relative output path (HostContext::resolveOutputPath).
std::string resolvedOutput(const EvaluatorOptions& o, const std::string& path) {
    const fs::path p(path);
    const std::string& base = o.outputDir.empty() ? o.inputBase : o.outputDir;
    if (p.is_absolute() || base.empty()) return p.string();
    return (fs::path(base) / p).lexically_normal().string();
}

}  // namespace darkroom::workflows::batch
