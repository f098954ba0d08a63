#include "foreach_run.h"

#include "cli.h"
#include "database_sinks.h"
#include "entry_scheduler.h"
#include "processes.h"

#include <darkroom/atomic_file.h>
#include <darkroom/error.h>
#include <darkroom/framework/cinema/csv.h>
#include <darkroom/framework/cinema/database.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <sstream>

namespace darkroom::cli {

namespace fs = std::filesystem;

namespace {

// out.png -> out_phi=30_theta=45.png, or the {entry} placeholder replaced.
std::string perEntryPath(const std::string& path, const std::string& entry) {
    std::string out = path;
    const std::string tag = "{entry}";
    if (out.find(tag) != std::string::npos) {
        for (auto pos = out.find(tag); pos != std::string::npos; pos = out.find(tag, pos + entry.size()))
            out.replace(pos, tag.size(), entry);
        return out;
    }
    const fs::path p(path);
    return (p.parent_path() / (p.stem().string() + "_" + entry + p.extension().string())).string();
}

struct OutputPort {
    std::string node, port, original;
};

// Every node that depends on `source` through edges (source included).
std::set<std::string> downstreamOf(const Graph& g, const std::string& source) {
    std::set<std::string> seen{source};
    std::vector<std::string> todo{source};
    while (!todo.empty()) {
        const std::string n = todo.back();
        todo.pop_back();
        for (const Edge& e : g.edges())
            if (e.from.node == n && seen.insert(e.to.node).second) todo.push_back(e.to.node);
    }
    return seen;
}

// The Path parameters of the output nodes that run per entry, to rename per
// entry. A sink fed the entry's row (a `row` input connected, as CinemaWriter
// has) names its entries itself: its paths stay as given.
std::vector<OutputPort> outputPorts(const Graph& g, const std::vector<std::string>& sinks) {
    std::vector<OutputPort> out;
    for (const auto& name : sinks) {
        const Node* n = g.node(name);
        if (g.ports(*n).input("row") && !g.edgesInto(name, "row").empty()) continue;
        for (const auto& p : g.ports(*n).inputs) {
            if (p.type != PortType::Path) continue;
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

// The index: the database's parameter columns, then one file column per
// output (FILE, or FILE_<node>[_<port>] for several), one row per entry in
// database order, file names relative to the index's folder.
void writeIndex(const std::string& path, const CinemaDatabase& db, const std::vector<OutputPort>& outputs,
                const std::map<std::size_t, std::vector<std::string>>& filesByRow) {
    std::map<std::string, int> portsPerNode;
    for (const auto& o : outputs) ++portsPerNode[o.node];
    std::string text;
    const auto parameters = db.parameterColumns();
    for (auto c : parameters) text += quoteCsvCell(db.columns()[c].name) + ",";
    for (std::size_t k = 0; k < outputs.size(); ++k) {
        std::string name = outputs.size() == 1 ? "FILE" : "FILE_" + outputs[k].node;
        if (outputs.size() > 1 && portsPerNode[outputs[k].node] > 1) name += "_" + outputs[k].port;
        text += quoteCsvCell(name) + (k + 1 < outputs.size() ? "," : "\n");
    }
    const fs::path folder = fs::absolute(fs::path(path)).parent_path();
    for (const auto& [row, files] : filesByRow) {
        for (auto c : parameters) text += quoteCsvCell(db.cell(row, c)) + ",";
        for (std::size_t k = 0; k < files.size(); ++k)
            text += quoteCsvCell(fs::absolute(files[k]).lexically_proximate(folder).string()) +
                    (k + 1 < files.size() ? "," : "\n");
    }
    if (!folder.empty()) fs::create_directories(folder);
    writeFileAtomic(path, text);
}

}  // namespace

int runForeach(Graph& g, Evaluator& ev, EvaluatorOptions& o, ProgressBar& bar, const ForeachSettings& s,
               const std::function<void(const std::string&, std::vector<std::string>)>& evaluate) {
    const Node* reader = g.node(s.node);
    if (!reader || !g.ports(*reader).input("database") || !g.ports(*reader).input("parameters")) {
        if (processes().root())
            reportError("--foreach " + s.node + ": expected the name of a CinemaReader node (with 'database' and 'parameters')");
        return kBadInput;
    }
    fs::path dbPath = currentValue(g, s.node, "database");
    if (dbPath.is_relative()) dbPath = fs::path(o.inputBase) / dbPath;
    std::optional<CinemaDatabase> opened;
    try {
        opened.emplace(CinemaDatabase::open(dbPath.string()));
    } catch (const Error& e) {
        // Every process opens the same database: one reports it.
        if (processes().root()) reportError(e.what());
        return kBadInput;
    }
    const CinemaDatabase& db = *opened;
    std::vector<std::size_t> rows;
    if (s.where.empty())
        for (std::size_t r = 0; r < db.rowCount(); ++r) rows.push_back(r);
    else
        rows = db.selectWhere(s.where);
    if (rows.empty()) {
        if (processes().root()) reportError(dbPath.string() + ": no entry matches '" + s.where + "'");
        return kBadInput;
    }
    // Sinks that depend on the entry run once per entry; the others (e.g. a
    // Movie of the database the entries are written to) once, after the last.
    const std::set<std::string> perEntry = downstreamOf(g, s.node);
    std::vector<std::string> entrySinks, finalSinks;
    for (const auto& sink : g.sinks()) (perEntry.count(sink) ? entrySinks : finalSinks).push_back(sink);
    if (entrySinks.empty()) std::swap(entrySinks, finalSinks);  // nothing reads the entry: every sink per entry
    const std::vector<OutputPort> outputs = outputPorts(g, entrySinks);
    std::vector<DatabaseSink> databases;
    try {
        databases = databaseSinks(g, entrySinks, o, processes().size > 1);
    } catch (const Error& e) {
        if (processes().root()) reportError(e.what());
        return kBadInput;
    }
    // Under mpirun each rank writes the entries it shades into a staging
    // database of its own; rank 0 adopts them all at the end (database_sinks.h).
    const bool staging = processes().size > 1 && !databases.empty();
    auto filesOf = [&](std::size_t row) {
        std::vector<std::string> files;
        for (const auto& out : outputs) files.push_back(resolvedOutput(o, perEntryPath(out.original, db.entryName(row))));
        return files;
    };

    // The root decides what a resume keeps, so every process works on the same list.
    std::unique_ptr<EntryScheduler> scheduler = makeEntryScheduler();
    // It also checks the databases against their nodes' modes first, so that
    // a refused one stops the run before any shading, reported once.
    const std::string refused = "refused";
    std::string todoText;
    if (scheduler->root()) {
        std::vector<std::set<std::string>> keptByDatabase;
        for (const auto& d : databases) {
            try {
                prepareDatabase(d);
                if (s.resume) keptByDatabase.push_back(entriesKeptByResume(d));
            } catch (const Error& e) {
                reportError(label(d) + ": " + e.what());
                todoText = refused;
                break;
            }
        }
        for (std::size_t k = 0; k < rows.size() && todoText != refused; ++k) {
            bool done = s.resume && !(outputs.empty() && databases.empty());
            for (const auto& f : filesOf(rows[k])) done = done && fs::is_regular_file(f) && fs::file_size(f) > 0;
            for (const auto& entries : keptByDatabase) done = done && entries.count(db.entryName(rows[k]));
            if (!done) todoText += std::to_string(k) + " ";
        }
    }
    scheduler->share(todoText);
    if (todoText == refused) return kBadInput;
    for (const auto& d : databases) {
        if (!staging) break;
        g.setParameter(d.node, "database", Value(stagingDatabase(d, processes().rank)));
        g.setParameter(d.node, "mode", Value(std::string("overwrite")));
    }
    std::vector<std::size_t> todo;
    {
        std::istringstream in(todoText);
        for (std::size_t k; in >> k;) todo.push_back(k);
    }
    const std::size_t kept = rows.size() - todo.size();

    scheduler->start(todo.size());
    std::string records;  // "position file file ..." per shaded entry
    bool failedHere = false;
    int failure = kOk;
    const double total = double(rows.size());
    while (const auto next = scheduler->next()) {
        const std::size_t position = todo[*next], row = rows[position];
        const std::string entry = db.entryName(row);
        g.setParameter(s.node, "parameters", Value(db.formatParameters(row)));
        for (const auto& out : outputs) g.setParameter(out.node, out.port, Value(perEntryPath(out.original, entry)));
        // Progress between entries counts every process's; during one, this
        // process's own fraction on top (MPI is called from this thread only).
        const double done = double(kept + scheduler->finishedEverywhere());
        bar.update(done / total, entry);
        o.onProgress = [&bar, done, total, entry](double f, const std::string&) { bar.update((done + f) / total, entry); };
        ev.setOptions(o);
        try {
            evaluate("entry " + entry + " (" + std::to_string(position + 1) + " of " + std::to_string(rows.size()) + ")",
                     entrySinks);
        } catch (const GraphError& e) {
            bar.finish();
            report(e.diagnostics());
            failure = kBadInput;
        } catch (const Cancelled&) {
            throw;
        } catch (const Error& e) {
            bar.finish();
            reportError("entry " + entry + ": " + e.what());
            failure = kRuntimeFailure;
        }
        if (failure != kOk) {
            failedHere = true;
            scheduler->failed();
            break;
        }
        records += std::to_string(position) + "\n";
        scheduler->finished();
    }
    // The writers release their staging databases (data.csv written a last
    // time, lock removed) before rank 0 reads them.
    if (staging) ev.clearCache();
    bool anyFailed = false;
    const std::vector<std::string> all = scheduler->gather(records, failedHere, anyFailed);
    bar.finish();
    // Also after a failure: the database then holds what was shaded, as one
    // process's would, and a resume completes it.
    for (const auto& d : databases) {
        if (!staging || !scheduler->root()) break;
        try {
            mergeStagedEntries(d);
        } catch (const Error& e) {
            reportError(label(d) + ": " + e.what());
            if (failure == kOk) failure = kRuntimeFailure;
        }
    }
    if (scheduler->root() && !s.index.empty()) {
        // Entries kept by the resume and entries shaded now, by any process.
        std::map<std::size_t, std::vector<std::string>> filesByRow;
        std::vector<bool> shaded(rows.size(), false);
        for (const auto& text : all) {
            std::istringstream in(text);
            for (std::size_t k; in >> k;) shaded[k] = true;
        }
        const std::set<std::size_t> redo(todo.begin(), todo.end());
        for (std::size_t k = 0; k < rows.size(); ++k)
            if (shaded[k] || !redo.count(k)) filesByRow[rows[k]] = filesOf(rows[k]);
        try {
            writeIndex(s.index, db, outputs, filesByRow);
        } catch (const Error& e) {
            reportError(e.what());
            if (failure == kOk) failure = kRuntimeFailure;
        }
    }
    if (scheduler->root() && all.size() > 1 && !s.quiet) {
        // How the dynamic scheduling shared the entries out.
        std::string counts;
        std::size_t shadedNow = 0;
        for (const auto& text : all) {
            const auto n = std::size_t(std::count(text.begin(), text.end(), '\n'));
            counts += (counts.empty() ? "" : ", ") + std::to_string(n);
            shadedNow += n;
        }
        std::fprintf(stderr, "darkroom: shaded %zu entries over %zu ranks (per rank: %s)%s\n", shadedNow, all.size(),
                     counts.c_str(), kept ? (", " + std::to_string(kept) + " kept by --resume").c_str() : "");
    }
    if (failure != kOk) return failure;
    if (anyFailed) return kRuntimeFailure;
    if (scheduler->root() && !finalSinks.empty()) {
        o.onProgress = [&bar](double f, const std::string& node) { bar.update(f, node); };
        ev.setOptions(o);
        try {
            evaluate("after the last entry", finalSinks);
        } catch (const GraphError& e) {
            bar.finish();
            report(e.diagnostics());
            return kBadInput;
        } catch (const Cancelled&) {
            throw;
        } catch (const Error& e) {
            bar.finish();
            reportError(std::string("after the last entry: ") + e.what());
            return kRuntimeFailure;
        }
        bar.finish();
    }
    return kOk;
}

}  // namespace darkroom::cli
