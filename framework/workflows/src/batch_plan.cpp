#include "batch_plan.h"

#include "batch_entries.h"
#include "entry_ports.h"

#include <darkroom/error.h>
#include <darkroom/core/path_overlap.h>

#include <algorithm>
#include <set>

namespace darkroom::workflows::batch {

namespace fs = std::filesystem;

std::vector<std::string> Plan::filesOf(std::size_t row) const {
    std::vector<std::string> files;
    for (const auto& out : outputs)
        files.push_back(resolvedOutput(options, perEntryPath(out.original, entryName(row), *db, row)));
    return files;
}

namespace {

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

// Sinks that depend on the entry run once per entry; the others once, after
// the last: those no entry reaches, and those that read what another sink
// wrote (a Movie connected to CinemaWriter's `written`).
void planSinks(const Graph& g, const BatchSettings& s, Plan& p) {
    const std::vector<std::string> sinks = g.sinks();
    const std::set<std::string> perEntry = g.downstreamOf({s.reader});
    for (const auto& sink : sinks) {
        bool readsAWrite = false;
        for (const auto& other : sinks) readsAWrite = readsAWrite || (other != sink && g.downstreamOf({other}).count(sink));
        (perEntry.count(sink) && !readsAWrite ? p.entrySinks : p.finalSinks).push_back(sink);
    }
    if (p.entrySinks.empty()) std::swap(p.entrySinks, p.finalSinks);  // nothing reads the entry: every sink per entry
}

// The sinks per entry and after, what they write, and the refusals that
// need no file system state: throws InputError.
void planOutputs(const Graph& g, const BatchSettings& s, int writers, Plan& p) {
    planSinks(g, s, p);
    p.outputs = outputPorts(g, p.entrySinks);
    try {
        p.databases = databaseSinks(g, p.entrySinks, p.options, writers > 1);
    } catch (const Error& e) {
        throw InputError(e.what());
    }
    p.staging = writers > 1 && !p.databases.empty();
    planAfterLast(g, p);
    // A database written over the one read would lose the products being
    // shaded (D1 of issue 26). The node refuses the same when it runs alone;
    // staged, only the merge would meet the source.
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

}  // namespace

Plan planBatch(const Graph& g, const BatchSettings& settings, EvaluatorOptions options, int processes, int lanes) {
    Plan p;
    p.options = std::move(options);
    openSource(g, settings, p);
    planOutputs(g, settings, processes * lanes, p);
    p.firstLaneInPlace = p.staging && processes == 1;
    return p;
}

}  // namespace darkroom::workflows::batch
