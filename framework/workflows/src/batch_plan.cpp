#include "batch_plan.h"

#include "entry_ports.h"

#include <darkroom/atomic_file.h>
#include <darkroom/error.h>
#include <darkroom/data/cinema/csv.h>
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

// The index's file columns: one per output path of the per-entry sinks and
// one per database a row-fed sink writes (its product of the entry); FILE
// alone, or FILE_<node>[_<port>] for several.
std::vector<std::string> indexColumns(const std::vector<OutputPort>& outputs,
                                      const std::vector<DatabaseSink>& databases) {
    std::map<std::string, int> portsPerNode;
    for (const auto& o : outputs) ++portsPerNode[o.node];
    const std::size_t count = outputs.size() + databases.size();
    std::vector<std::string> names;
    for (const auto& o : outputs)
        names.push_back(count == 1 ? "FILE" : "FILE_" + o.node + (portsPerNode[o.node] > 1 ? "_" + o.port : ""));
    for (const auto& d : databases) names.push_back(count == 1 ? "FILE" : "FILE_" + d.node);
    return names;
}

// The index: the database's parameter columns, then the file columns, one
// row per entry in database order, file names relative to the index's folder.
void writeIndex(const std::string& path, const CinemaDatabase& db, const std::vector<std::string>& fileColumns,
                const std::map<std::size_t, std::vector<std::string>>& filesByRow) {
    const fs::path folder = fs::absolute(fs::path(path)).parent_path();
    std::vector<std::string> cells;
    const auto line = [&cells]() {
        std::string text;
        for (std::size_t k = 0; k < cells.size(); ++k) text += (k ? "," : "") + quoteCsvCell(cells[k]);
        cells.clear();
        return text + "\n";
    };
    const auto parameters = db.parameterColumns();
    for (auto c : parameters) cells.push_back(db.columns()[c].name);
    cells.insert(cells.end(), fileColumns.begin(), fileColumns.end());
    std::string text = line();
    for (const auto& [row, files] : filesByRow) {
        for (auto c : parameters) cells.push_back(db.cell(row, c));
        for (const auto& f : files) cells.push_back(fs::absolute(f).lexically_proximate(folder).string());
        text += line();
    }
    if (!folder.empty()) fs::create_directories(folder);
    writeFileAtomic(path, text);
}

GraphEdits::~GraphEdits() {
    // Parameters first (an input given a path in place of its edge loses it),
    // then the edges; the values were the graph's, so nothing is refused.
    try {
        for (auto it = parameters_.rbegin(); it != parameters_.rend(); ++it) {
            if (it->value) g_.setParameter(it->node, it->port, *it->value);
            else g_.clearParameter(it->node, it->port);
        }
        for (const Edge& e : edges_) g_.connect(e.from, e.to);
    } catch (...) {
        // A graph the batch cannot put back is left as the batch made it.
    }
}

void GraphEdits::set(const std::string& node, const std::string& port, Value value) {
    const bool known = std::any_of(parameters_.begin(), parameters_.end(),
                                   [&](const Saved& s) { return s.node == node && s.port == port; });
    if (!known) {
        const Value* before = g_.node(node)->parameter(port);
        parameters_.push_back({node, port, before ? std::optional<Value>(*before) : std::nullopt});
    }
    g_.setParameter(node, port, std::move(value));
}

void GraphEdits::disconnect(const Edge& e) {
    g_.disconnect(e.from, e.to);
    edges_.push_back(e);
}

}  // namespace darkroom::workflows::batch
