#include "foreach_run.h"

#include "cli.h"
#include "database_sinks.h"
#include "entry_scheduler.h"
#include "processes.h"

#include <darkroom/atomic_file.h>
#include <darkroom/error.h>
#include <darkroom/data/cinema/csv.h>
#include <darkroom/data/cinema/database.h>

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

// "" when every entry has files of its own; else a message naming the
// first two entries that would write the same file.
template <class FilesOf>
std::string sharedOutputFile(const std::vector<std::size_t>& rows, const FilesOf& filesOf, const CinemaDatabase& db) {
    std::map<std::string, std::size_t> owner;
    for (const std::size_t row : rows)
        for (const auto& f : filesOf(row)) {
            const auto [it, fresh] = owner.emplace(fs::absolute(f).lexically_normal().string(), row);
            if (!fresh && it->second != row)
                return "--foreach: the entries " + db.formatParameters(it->second) + " and " +
                       db.formatParameters(row) + " would both be written to " + f +
                       " (in file names every character but letters, digits and . + - becomes ~); "
                       "nothing was shaded";
        }
    return "";
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

    // Two entries whose parameters give one file name (a/b and a~b both
    // become a~b) would overwrite each other: refused before any shading.
    if (const std::string clash = sharedOutputFile(rows, filesOf, db); !clash.empty()) {
        if (processes().root()) reportError(clash);
        return kBadInput;
    }
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
                prepareDatabase(d, staging);
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
        for (std::size_t k = 0; k < rows.size(); ++k) {
            if (!shaded[k] && redo.count(k)) continue;
            auto files = filesOf(rows[k]);
            for (const auto& d : databases)
                files.push_back((fs::path(d.database) / (db.entryName(rows[k]) + "." + d.format)).string());
            filesByRow[rows[k]] = std::move(files);
        }
        try {
            writeIndex(s.index, db, indexColumns(outputs, databases), filesByRow);
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
