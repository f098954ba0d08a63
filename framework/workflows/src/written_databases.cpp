#include <darkroom/workflows/written_databases.h>

#include <darkroom/atomic_file.h>
#include <darkroom/error.h>
#include <darkroom/data/cinema/csv.h>
#include <darkroom/data/cinema/naming.h>
#include <darkroom/data/cinema/pipeline_origin.h>
#include <darkroom/data/cinema/writer.h>
#include <darkroom/workflows/staging.h>

#include "entry_ports.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <filesystem>

namespace darkroom::workflows {

namespace fs = std::filesystem;

namespace {

std::string valueOf(const Graph& g, const Node& n, const std::string& port) {
    if (const Value* v = n.parameter(port)) return v->asString();
    const PortSpec* spec = g.ports(n).input(port);
    return spec ? spec->defaultValue.asString() : std::string();
}

CinemaWriterOptions modeOptions(const DatabaseSink& sink) {
    CinemaWriterOptions o;
    o.overwrite = sink.mode == "overwrite";
    o.resume = sink.mode == "resume";
    adviseNodeMode(o, sink.node);
    return o;
}

}  // namespace

std::vector<DatabaseSink> databaseSinks(const Graph& g, const std::vector<std::string>& sinks,
                                        const EvaluatorOptions& o, bool overRanks) {
    std::vector<DatabaseSink> out;
    for (const auto& name : sinks) {
        const Node* n = g.node(name);
        const PortSpec* database = writerDatabase(g, *n);
        if (!isFedARow(g, *n) || !database) continue;
        DatabaseSink sink{name,
                          n->type,
                          database->name,
                          valueOf(g, *n, database->name),
                          valueOf(g, *n, "mode"),
                          valueOf(g, *n, "format"),
                          g.ports(*n).input("pipeline") ? valueOf(g, *n, "pipeline") : std::string()};
        if (writesADatabaseThroughAnEdge(g, *n)) {
            if (!overRanks) continue;
            throw Error(label(sink) + ": its database comes through an edge; under mpirun give it as a "
                                      "parameter, so that the runner can stage each rank's entries");
        }
        if (sink.database.empty()) continue;  // the node says so at its first entry
        // As HostContext::resolveOutputPath, then lexically normal like the node.
        const fs::path p(sink.database);
        const std::string& base = o.outputDir.empty() ? o.inputBase : o.outputDir;
        sink.database = (p.is_absolute() || base.empty() ? p : fs::path(base) / p).lexically_normal().string();
        while (sink.database.size() > 1 && sink.database.back() == '/') sink.database.pop_back();
        out.push_back(std::move(sink));
    }
    return out;
}

std::string label(const DatabaseSink& sink) { return "node '" + sink.node + "' (" + sink.type + ")"; }

std::string stagingFolder(const DatabaseSink& sink) { return sink.database + ".staging"; }

std::string stagingDatabase(const DatabaseSink& sink, int rank) {
    // Absolute: the node resolves a relative path against the output folder again.
    return fs::absolute(fs::path(stagingFolder(sink)) / ("rank-" + std::to_string(rank))).lexically_normal().string();
}

namespace {

// File system errors as darkroom::Error, like the writer's own.
template <class F>
auto withFileErrors(F&& f) {
    try {
        return f();
    } catch (const fs::filesystem_error& e) {
        throw Error(e.what());
    }
}

// Whether <database>.staging exists; throws when it exists but Darkroom did
// not make it (no marker inside): such a folder is never read nor removed.
bool ownStagingFolder(const DatabaseSink& sink) {
    const fs::path folder = stagingFolder(sink);
    std::error_code ec;
    const auto st = fs::symlink_status(folder, ec);
    if (!fs::exists(st)) return false;
    if (!fs::is_directory(st) || !fs::is_regular_file(fs::symlink_status(folder / workflows::kStagingMarker, ec)))
        throw Error(fmt::format("{} exists and Darkroom did not make it (no {} inside); runs over MPI ranks or "
                                "with several entries in flight stage their entries there, so move it away "
                                "(nothing in it was touched)",
                                folder.string(), workflows::kStagingMarker));
    return true;
}

// A resume adds entries to what an earlier run wrote: refused when that run's
// pipeline was another (D6 of issue 26), before anything is shaded.
void checkSamePipeline(const DatabaseSink& sink, const std::string& database) {
    if (sink.mode != "resume" || sink.pipeline.empty() || !fs::is_regular_file(fs::path(database) / "data.csv")) return;
    const std::string change =
        describePipelineChange(CinemaWriter::recordedOrigin(database), pipelineOriginItems(sink.pipeline));
    if (!change.empty())
        throw InputError(fmt::format("cannot resume {}: {} changed since the database was begun ({}); its entries "
                                     "would mix with entries shaded otherwise. Set mode to overwrite to start afresh",
                                     database, kUpstreamPipelineSource, change));
}

void prepare(const DatabaseSink& sink) {
    CinemaWriter::check(sink.database, modeOptions(sink));
    checkSamePipeline(sink, sink.database);
    const fs::path folder = stagingFolder(sink);
    if (!ownStagingFolder(sink)) return;
    // A staging database that is locked is being written by a run now.
    CinemaWriterOptions resume;
    resume.resume = true;
    for (const auto& part : workflows::stagingDatabases(folder)) {
        CinemaWriter::check(part.string(), resume);
        checkSamePipeline(sink, part.string());
    }
    if (sink.mode == "resume") {
        mergeStagedEntries(sink, false);
        return;
    }
    const std::size_t staged = workflows::readStagedDatabases(stagingFolder(sink)).entries.size();
    if (sink.mode != "overwrite" && staged > 0)
        throw Error(fmt::format("database {}: an interrupted run left {} entries staged in {}; "
                                "set mode to resume to complete the database with them, or to overwrite to "
                                "start afresh",
                                sink.database, staged, folder.string()));
    fs::remove_all(folder);
}

void merge(const DatabaseSink& sink, bool keepWritten) {
    const fs::path folder = stagingFolder(sink);
    if (!ownStagingFolder(sink)) return;
    workflows::StagedEntries staged = workflows::readStagedDatabases(stagingFolder(sink));
    if (!staged.entries.empty()) {
        CinemaWriterOptions o = staged.options;
        const CinemaWriterOptions mode = modeOptions(sink);
        o.overwrite = mode.overwrite;
        o.resume = mode.resume;
        o.overwriteAdvice = mode.overwriteAdvice;
        o.resumeAdvice = mode.resumeAdvice;
        if (keepWritten) {
            o.overwrite = false;
            o.resume = true;
        }
        CinemaWriter w(sink.database, staged.columns, o);
        // As the node does alone: a resumed database keeps the entries it has.
        std::vector<CinemaStagedEntry> adopt;
        for (auto& e : staged.entries)
            if (!o.resume || !w.hasEntry(e.parameters)) adopt.push_back(std::move(e));
        w.adoptEntries(adopt);
        w.finish();
    }
    fs::remove_all(folder);
}

std::set<std::string> keptEntries(const DatabaseSink& sink) {
    std::set<std::string> kept;
    const fs::path csv = fs::path(sink.database) / "data.csv";
    if (sink.mode != "resume" || !fs::is_regular_file(csv)) return kept;
    CsvReadOptions strict;
    strict.strict = true;
    const CsvTable t = readCsvFile(csv.string(), strict);
    const auto fileColumn = std::find(t.header.begin(), t.header.end(), "FILE");
    if (fileColumn == t.header.end()) return kept;  // the writer refuses it at the first entry
    const std::size_t f = std::size_t(fileColumn - t.header.begin());
    for (const auto& row : t.rows) {
        // What the writer's resume keeps: the product under the name its
        // parameters give, in the node's format, and every attachment.
        std::vector<std::pair<std::string, std::string>> parameters;
        for (std::size_t c = 0; c < f; ++c) parameters.emplace_back(t.header[c], row[c]);
        const std::string entry = cinemaEntryName(parameters);
        if (row[f] != entry + (sink.format.empty() ? fs::path(row[f]).extension().string() : "." + sink.format))
            continue;
        std::error_code ec;
        const fs::path product = fs::path(sink.database) / row[f];
        bool complete = fs::is_regular_file(product, ec) && fs::file_size(product, ec) > 0;
        for (std::size_t k = f + 1; k < row.size(); ++k)
            complete = complete && fs::is_regular_file(fs::path(sink.database) / row[k], ec);
        if (complete) kept.insert(entry);
    }
    return kept;
}

void beginStaging(const DatabaseSink& sink) {
    const fs::path folder = stagingFolder(sink);
    if (ownStagingFolder(sink)) return;
    fs::create_directories(folder);
    writeFileAtomic((folder / workflows::kStagingMarker).string(),
                    "Darkroom stages the entries of " + sink.database + " here during a run over MPI ranks or with several entries in flight.\n");
}

}  // namespace

void prepareDatabase(const DatabaseSink& sink, bool overRanks) {
    withFileErrors([&] {
        prepare(sink);
        if (overRanks) beginStaging(sink);
    });
}

void mergeStagedEntries(const DatabaseSink& sink, bool keepWritten) {
    withFileErrors([&] { merge(sink, keepWritten); });
}

std::set<std::string> entriesKeptByResume(const DatabaseSink& sink) {
    return withFileErrors([&] { return keptEntries(sink); });
}

}  // namespace darkroom::workflows
