#include <darkroom/workflows/batch.h>

#include "batch_entries.h"
#include "batch_plan.h"
#include "entry_ports.h"

#include <darkroom/error.h>
#include <darkroom/core/path_overlap.h>
#include <darkroom/data/cinema/database.h>
#include <darkroom/workflows/written_databases.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <optional>
#include <sstream>

namespace darkroom::workflows {

namespace fs = std::filesystem;
using namespace batch;

namespace {

// What the batch shades and writes, the same on every process.
struct Plan {
    fs::path source;  // the database read
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
    bool staging = false;  // several processes write databases: each into its staging database
    EvaluatorOptions options;

    const std::string& entryName(std::size_t row) const { return names.at(row); }

    // The files entry `row` writes through the renamed output paths.
    std::vector<std::string> filesOf(std::size_t row) const {
        std::vector<std::string> files;
        for (const auto& out : outputs)
            files.push_back(resolvedOutput(options, perEntryPath(out.original, entryName(row), *db, row)));
        return files;
    }
};

// "" when every entry has files of its own; else a message naming the
// first two entries that would write the same file.
std::string sharedOutputFile(const Plan& p) {
    std::map<std::string, std::size_t> owner;
    for (const std::size_t row : p.rows)
        for (const auto& f : p.filesOf(row)) {
            const auto [it, fresh] = owner.emplace(fs::absolute(f).lexically_normal().string(), row);
            if (!fresh && it->second != row)
                return "--foreach: the entries " + p.db->formatParameters(it->second) + " and " +
                       p.db->formatParameters(row) + " would both be written to " + f +
                       " (in file names every character but letters, digits and . + - becomes ~); "
                       "nothing was shaded";
        }
    return "";
}

// The database read and the selected rows; throws InputError.
void openSource(const Graph& g, const BatchSettings& s, Plan& p) {
    const Node* reader = g.node(s.reader);
    const PortSpec* database = reader ? entryReaderDatabase(g, *reader) : nullptr;
    if (!database)
        throw InputError("--foreach " + s.reader +
                         ": expected the name of a node that reads a database entry by entry, such as CinemaReader "
                         "(a row output, a path input for the database and an integer input 'entry')");
    p.source = currentValue(g, s.reader, database->name);
    if (p.source.is_relative()) p.source = fs::path(p.options.inputBase) / p.source;
    // Named as the node names its own failures: the database is its parameter.
    try {
        p.db.emplace(CinemaDatabase::open(p.source.string()));
    } catch (const Error& e) {
        throw InputError("node '" + s.reader + "' (" + reader->type + "): " + e.what());
    }
    std::vector<std::size_t> selected;
    if (s.where.empty())
        for (std::size_t r = 0; r < p.db->rowCount(); ++r) selected.push_back(r);
    else
        selected = p.db->selectWhere(s.where);
    if (selected.empty()) throw InputError(p.source.string() + ": no entry matches '" + s.where + "'");
    try {
        BatchEntries entries = batchEntries(*p.db, selected);
        p.rows = std::move(entries.rows);
        p.names = std::move(entries.names);
    } catch (const Error& e) {
        throw InputError("node '" + s.reader + "' (" + reader->type + "): " + e.what());
    }
}

// What reads a per-entry sink's output: only a sink run after the last entry,
// directly, from a database sink (Movie from CinemaWriter's `written`), which
// then gets the database's final path; throws InputError for anything else.
void planAfterLast(const Graph& g, Plan& p) {
    const auto in = [](const std::vector<std::string>& names, const std::string& n) {
        return std::find(names.begin(), names.end(), n) != names.end();
    };
    for (const Edge& e : g.edges()) {
        if (!in(p.entrySinks, e.from.node)) continue;
        const auto d = std::find_if(p.databases.begin(), p.databases.end(),
                                    [&](const DatabaseSink& x) { return x.node == e.from.node; });
        if (d == p.databases.end() || !in(p.finalSinks, e.to.node))
            throw InputError("--foreach: node '" + e.to.node + "' reads " + e.from.str() +
                             ", which is written entry by entry; only a node that writes (such as Movie) may read "
                             "it, directly, and only the database of a CinemaWriter fed the reader's row: it then "
                             "runs once, after the last entry");
        p.afterLast.emplace_back(e, fs::absolute(d->database).lexically_normal().string());
    }
}

// The sinks per entry and after, what they write, and the refusals that
// need no file system state: throws InputError.
void planOutputs(const Graph& g, const BatchSettings& s, bool overRanks, Plan& p) {
    // Sinks that depend on the entry run once per entry; the others once,
    // after the last: those no entry reaches, and those that read what
    // another sink wrote (a Movie connected to CinemaWriter's `written`).
    const std::vector<std::string> sinks = g.sinks();
    const std::set<std::string> perEntry = g.downstreamOf({s.reader});
    for (const auto& sink : sinks) {
        bool readsAWrite = false;
        for (const auto& other : sinks) readsAWrite = readsAWrite || (other != sink && g.downstreamOf({other}).count(sink));
        (perEntry.count(sink) && !readsAWrite ? p.entrySinks : p.finalSinks).push_back(sink);
    }
    if (p.entrySinks.empty()) std::swap(p.entrySinks, p.finalSinks);  // nothing reads the entry: every sink per entry
    p.outputs = outputPorts(g, p.entrySinks);
    try {
        p.databases = databaseSinks(g, p.entrySinks, p.options, overRanks);
    } catch (const Error& e) {
        throw InputError(e.what());
    }
    p.staging = overRanks && !p.databases.empty();
    planAfterLast(g, p);
    // A database written over the one read would lose the products being
    // shaded (D1 of issue 26). The node refuses the same when it runs alone;
    // under mpirun it writes a staging database, and only the merge would
    // meet the source.
    for (const auto& d : p.databases)
        if (pathsOverlap(d.database, p.source.string()))
            throw InputError(label(d) + ": the output " + d.database + " " +
                             overlapWording(d.database, p.source.string()) + " " + absoluteNormal(p.source.string()) +
                             ", the database node '" + s.reader +
                             "' reads; writing there would destroy the input. Choose an output outside the inputs");
    // Two entries whose parameters give one file name (a/b and a~b both
    // become a~b) would overwrite each other.
    if (const std::string clash = sharedOutputFile(p); !clash.empty()) throw InputError(clash);
}

// The positions in p.rows still to shade, the same on every process: the
// lead checks the databases against their writers' modes (a refusal stops
// the run before any shading) and decides what a resume keeps.
std::vector<std::size_t> agreeTodo(const BatchSettings& s, const Plan& p, ProcessGroup& group) {
    std::string todo, refused;
    if (group.lead()) {
        std::vector<std::set<std::string>> keptByDatabase;
        for (const auto& d : p.databases) {
            try {
                prepareDatabase(d, p.staging);
                if (s.resume) keptByDatabase.push_back(entriesKeptByResume(d));
            } catch (const Error& e) {
                refused = label(d) + ": " + e.what();
                break;
            }
        }
        for (std::size_t k = 0; k < p.rows.size() && refused.empty(); ++k) {
            bool done = s.resume && !(p.outputs.empty() && p.databases.empty());
            for (const auto& f : p.filesOf(p.rows[k])) done = done && fs::is_regular_file(f) && fs::file_size(f) > 0;
            for (const auto& entries : keptByDatabase) done = done && entries.count(p.db->entryName(p.rows[k]));
            if (!done) todo += std::to_string(k) + " ";
        }
    }
    if (const std::string e = group.agreedError(refused); !e.empty()) throw InputError(e);
    group.broadcast(todo);
    std::vector<std::size_t> out;
    std::istringstream in(todo);
    for (std::size_t k; in >> k;) out.push_back(k);
    return out;
}

// Shades this process's share of `todo`; returns the positions it shaded,
// one per line. An entry that fails ends this process's share (`failure`)
// and stops the others taking more.
std::string shadeShare(GraphEdits& g, Evaluator& ev, const BatchSettings& s, const Plan& p,
                       const std::vector<std::size_t>& todo, ProcessGroup& group, const BatchCallbacks& cb,
                       std::exception_ptr& failure) {
    const std::unique_ptr<WorkQueue> queue = group.workQueue(todo.size());
    const std::size_t kept = p.rows.size() - todo.size();
    const double total = double(p.rows.size());
    EvaluatorOptions o = p.options;
    std::string records;
    while (const auto next = queue->next()) {
        const std::size_t position = todo[*next], row = p.rows[position];
        const std::string entry = p.entryName(row);
        g.set(s.reader, kEntryPort, Value(std::int64_t(row)));
        for (const auto& out : p.outputs) g.set(out.node, out.port, Value(perEntryPath(out.original, entry, *p.db, row)));
        // Progress between entries counts every process's; during one, this
        // process's own fraction on top.
        const double done = double(kept + queue->finishedEverywhere());
        if (cb.progress && group.lead()) cb.progress(done / total, entry);
        o.onProgress = [&cb, &group, done, total, entry](double f, const std::string&) {
            if (cb.progress && group.lead()) cb.progress((done + f) / total, entry);
        };
        ev.setOptions(o);
        try {
            cb.evaluate("entry " + entry + " (" + std::to_string(position + 1) + " of " +
                            std::to_string(p.rows.size()) + ")",
                        p.entrySinks);
        } catch (const Cancelled&) {
            throw;
        } catch (const GraphError&) {
            failure = std::current_exception();
        } catch (const Error& e) {
            failure = std::make_exception_ptr(Error("entry " + entry + ": " + e.what(), e.node()));
        }
        if (failure) {
            queue->failed();
            break;
        }
        records += std::to_string(position) + "\n";
        queue->finished();
    }
    return records;
}

// The entries this process shades, as one sequence of the evaluator: a
// CinemaWriter keeps its database open across them and lets it go (data.csv
// written a last time, the lock removed) as the sequence ends — before the
// lead reads the staging databases. A failure to let go fails the batch.
std::string shadeInSequence(GraphEdits& g, Evaluator& ev, const BatchSettings& s, const Plan& p,
                            const std::vector<std::size_t>& todo, ProcessGroup& group, const BatchCallbacks& cb,
                            std::exception_ptr& failure) {
    EvaluatorSequence sequence(ev, SequenceInfo{group.size() == 1 ? todo.size() : 0});
    std::string records = shadeShare(g, ev, s, p, todo, group, cb, failure);
    if (failure) return records;  // the sequence ends as not completed
    try {
        sequence.end();
    } catch (const Error&) {
        failure = std::current_exception();
    }
    return records;
}

}  // namespace

namespace {

// The positions every process shaded (on the lead), and whether any failed.
std::vector<std::string> gatherRecords(const std::string& mine, bool failedHere, ProcessGroup& group, bool& anyFailed) {
    anyFailed = !group.agreedError(failedHere ? "failed" : "").empty();
    std::vector<std::string> all = group.allGather(mine);
    if (!group.lead()) all.clear();
    return all;
}

// The index of the entries kept by the resume and shaded now, by any process.
void writeIndexOf(const BatchSettings& s, const Plan& p, const std::vector<std::size_t>& todo,
                  const std::vector<std::string>& all) {
    std::map<std::size_t, std::vector<std::string>> filesByRow;
    std::vector<bool> shaded(p.rows.size(), false);
    for (const auto& text : all) {
        std::istringstream in(text);
        for (std::size_t k; in >> k;) shaded[k] = true;
    }
    const std::set<std::size_t> redo(todo.begin(), todo.end());
    for (std::size_t k = 0; k < p.rows.size(); ++k) {
        if (!shaded[k] && redo.count(k)) continue;
        auto files = p.filesOf(p.rows[k]);
        for (const auto& d : p.databases)
            files.push_back((fs::path(d.database) / (p.db->entryName(p.rows[k]) + "." + d.format)).string());
        filesByRow[p.rows[k]] = std::move(files);
    }
    writeIndex(s.index, *p.db, indexColumns(p.outputs, p.databases), filesByRow);
}

// On the lead, after every process has finished: the staged entries merged
// (also after a failure, so the database holds what was shaded and a resume
// completes it), and the index. The first failure is kept.
void finishOnLead(const BatchSettings& s, const Plan& p, const std::vector<std::size_t>& todo,
                  const std::vector<std::string>& all, std::exception_ptr& failure) {
    const auto keep = [&failure](const std::string& message) {
        if (!failure) failure = std::make_exception_ptr(Error(message));
    };
    for (const auto& d : p.databases) {
        if (!p.staging) break;
        try {
            mergeStagedEntries(d);
        } catch (const Error& e) {
            keep(label(d) + ": " + e.what());
        }
    }
    if (s.index.empty()) return;
    try {
        writeIndexOf(s, p, todo, all);
    } catch (const Error& e) {
        keep(e.what());
    }
}

// The sinks that run once after the last entry, on the lead, reading the
// databases the entries were written into (the graph is rewired for it).
void runFinalSinks(GraphEdits& g, Evaluator& ev, const Plan& p, ProcessGroup& group, const BatchCallbacks& cb,
                   std::exception_ptr& failure) {
    if (!group.lead() || p.finalSinks.empty()) return;
    for (const auto& [edge, database] : p.afterLast) {
        g.disconnect(edge);
        g.set(edge.to.node, edge.to.port, Value(database));
    }
    EvaluatorOptions o = p.options;
    o.onProgress = [&cb](double f, const std::string& node) {
        if (cb.progress) cb.progress(f, node);
    };
    ev.setOptions(o);
    try {
        cb.evaluate("after the last entry", p.finalSinks);
    } catch (const Cancelled&) {
        throw;
    } catch (const GraphError&) {
        failure = std::current_exception();
    } catch (const Error& e) {
        failure = std::make_exception_ptr(Error(std::string("after the last entry: ") + e.what(), e.node()));
    }
}

}  // namespace

BatchSummary shadeEntries(Graph& graph, Evaluator& evaluator, EvaluatorOptions options, const BatchSettings& settings,
                          ProcessGroup& group, const BatchCallbacks& callbacks) {
    BatchCallbacks cb = callbacks;
    if (!cb.evaluate)
        cb.evaluate = [&](const std::string&, const std::vector<std::string>& sinks) { evaluator.run(graph, sinks); };
    Plan p;
    p.options = std::move(options);
    // Every process opens the same database and meets the same problems.
    GraphEdits edits(graph);  // undone as this returns
    openSource(graph, settings, p);
    planOutputs(graph, settings, group.size() > 1, p);
    const std::vector<std::size_t> todo = agreeTodo(settings, p, group);
    // Under several processes each writes the entries it shades into a
    // staging database of its own; the lead adopts them all at the end.
    for (const auto& d : p.databases) {
        if (!p.staging) break;
        edits.set(d.node, d.port, Value(stagingDatabase(d, group.rank())));
        edits.set(d.node, "mode", Value(std::string("overwrite")));
    }
    // The selection is "the whole database" to what spans every entry
    // (ColorMapping's database range), when the reader can say so.
    if (!settings.where.empty() && graph.ports(*graph.node(settings.reader)).input(kSelectionPort))
        edits.set(settings.reader, kSelectionPort, Value(settings.where));
    BatchSummary summary;
    summary.selected = p.rows.size();
    summary.kept = p.rows.size() - todo.size();
    const std::string records = shadeInSequence(edits, evaluator, settings, p, todo, group, cb, summary.failure);
    bool anyFailed = false;
    const std::vector<std::string> all = gatherRecords(records, bool(summary.failure), group, anyFailed);
    summary.failedElsewhere = anyFailed && !summary.failure;
    for (const auto& text : all) summary.shadedPerProcess.push_back(std::size_t(std::count(text.begin(), text.end(), '\n')));
    if (group.lead()) finishOnLead(settings, p, todo, all, summary.failure);
    if (!summary.failure && !anyFailed) runFinalSinks(edits, evaluator, p, group, cb, summary.failure);
    return summary;
}

}  // namespace darkroom::workflows
