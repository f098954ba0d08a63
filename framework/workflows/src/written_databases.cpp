#include "database_sinks.h"

#include <darkroom/atomic_file.h>
#include <darkroom/error.h>
#include <darkroom/data/cinema/csv.h>
#include <darkroom/data/cinema/naming.h>
#include <darkroom/data/cinema/writer.h>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <filesystem>

namespace darkroom::cli {

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
    return o;
}

// What the staging databases hold complete, in the order of their folders
// and rows, with the columns and file naming they were written with.
struct Staged {
    std::vector<std::string> columns;
    CinemaWriterOptions options;  // product extension and attachment columns
    std::vector<CinemaStagedEntry> entries;
};

// The file that marks a staging folder as Darkroom's: without it, the folder
// is someone else's and is neither read nor removed.
constexpr const char* kStagingMarker = ".darkroom-staging";

bool isRankFolderName(const std::string& name) {
    return name.size() > 5 && name.compare(0, 5, "rank-") == 0 &&
           std::all_of(name.begin() + 5, name.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// The staging databases: real folders named rank-<k> (never links).
std::vector<fs::path> stagingDatabases(const fs::path& folder) {
    std::vector<fs::path> parts;
    std::error_code ec;
    if (!fs::is_directory(fs::symlink_status(folder, ec))) return parts;
    for (const auto& e : fs::directory_iterator(folder))
        if (fs::is_directory(e.symlink_status()) && isRankFolderName(e.path().filename().string()))
            parts.push_back(e.path());
    std::sort(parts.begin(), parts.end());
    return parts;
}

// A staged file as data.csv names it: a plain file name inside its staging
// database, a regular file there (not a link). Anything else is refused,
// so a planted data.csv can never make the merge move a file in from outside.
fs::path stagedFile(const fs::path& part, const std::string& cell, const fs::path& csv) {
    const fs::path name(cell);
    if (cell.empty() || cell == "." || cell == ".." || cell.find('/') != std::string::npos ||
        cell.find('\0') != std::string::npos || name.filename() != name)
        throw Error(fmt::format("{}: '{}' is not a file name inside the staging database {}; refusing to adopt it",
                                csv.string(), cell, part.string()));
    const fs::path file = part / name;
    std::error_code ec;
    const auto st = fs::symlink_status(file, ec);
    if (fs::exists(st) && !fs::is_regular_file(st))
        throw Error(fmt::format("{}: '{}' is not a plain file (a link or a folder); refusing to adopt it",
                                csv.string(), file.string()));
    return file;
}

Staged readStaged(const DatabaseSink& sink) {
    Staged out;
    std::vector<std::string> header;
    fs::path first;
    for (const auto& part : stagingDatabases(stagingFolder(sink))) {
        const fs::path csv = part / "data.csv";
        if (!fs::is_regular_file(csv)) continue;  // a rank stopped before its first entry
        CsvReadOptions strict;
        strict.strict = true;
        const CsvTable t = readCsvFile(csv.string(), strict);
        const auto fileColumn = std::find(t.header.begin(), t.header.end(), "FILE");
        if (fileColumn == t.header.end())
            throw Error(fmt::format("{}: no FILE column; {} is not a staging database Darkroom wrote", csv.string(),
                                    part.string()));
        if (header.empty()) {
            header = t.header;
            first = part;
            // What the node recorded there, for the database to record (and a resume to compare).
            out.options.origin = CinemaWriter::recordedOrigin(part.string());
        } else if (t.header != header) {
            throw Error(fmt::format("the staging databases {} and {} have different columns ({} and {}); they "
                                    "come from different pipelines",
                                    first.string(), part.string(), fmt::join(header, ","), fmt::join(t.header, ",")));
        }
        const std::size_t f = std::size_t(fileColumn - t.header.begin());
        for (const auto& row : t.rows) {
            // Files are renamed into place whole: one that exists is complete.
            std::error_code ec;
            CinemaStagedEntry e;
            e.product = stagedFile(part, row[f], csv).string();
            bool complete = fs::is_regular_file(e.product, ec) && fs::file_size(e.product, ec) > 0;
            for (std::size_t k = f + 1; k < row.size(); ++k) {
                e.attachments[t.header[k]] = stagedFile(part, row[k], csv).string();
                complete = complete && fs::is_regular_file(e.attachments[t.header[k]], ec);
            }
            if (!complete) continue;  // shaded again
            for (std::size_t c = 0; c < f; ++c) e.parameters.emplace(t.header[c], CinemaValue(row[c]));
            if (out.entries.empty()) {
                // The naming the writer used: "<entry><extension>", "<entry><suffix>".
                out.options.productExtension = fs::path(row[f]).extension().string();
                const std::string entry = row[f].substr(0, row[f].size() - out.options.productExtension.size());
                for (std::size_t k = f + 1; k < row.size(); ++k)
                    out.options.attachments.push_back({t.header[k], row[k].substr(std::min(entry.size(), row[k].size()))});
            }
            out.entries.push_back(std::move(e));
        }
        out.columns.assign(header.begin(), header.begin() + std::ptrdiff_t(f));
    }
    return out;
}

}  // namespace

std::vector<DatabaseSink> databaseSinks(const Graph& g, const std::vector<std::string>& sinks,
                                        const EvaluatorOptions& o, bool overRanks) {
    std::vector<DatabaseSink> out;
    for (const auto& name : sinks) {
        const Node* n = g.node(name);
        const PortSpec* database = g.ports(*n).input("database");
        if (!g.ports(*n).input("row") || g.edgesInto(name, "row").empty() || !database ||
            database->type != PortType::Path)
            continue;
        DatabaseSink sink{name, n->type, valueOf(g, *n, "database"), valueOf(g, *n, "mode"), valueOf(g, *n, "format")};
        if (!g.edgesInto(name, "database").empty()) {
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
    if (!fs::is_directory(st) || !fs::is_regular_file(fs::symlink_status(folder / kStagingMarker, ec)))
        throw Error(fmt::format("{} exists and Darkroom did not make it (no {} inside); runs over MPI ranks stage "
                                "their entries there, so move it away (nothing in it was touched)",
                                folder.string(), kStagingMarker));
    return true;
}

void prepare(const DatabaseSink& sink) {
    CinemaWriter::check(sink.database, modeOptions(sink));
    const fs::path folder = stagingFolder(sink);
    if (!ownStagingFolder(sink)) return;
    // A staging database that is locked is being written by a run now.
    CinemaWriterOptions resume;
    resume.resume = true;
    for (const auto& part : stagingDatabases(folder)) CinemaWriter::check(part.string(), resume);
    if (sink.mode == "resume") {
        mergeStagedEntries(sink);
        return;
    }
    const std::size_t staged = readStaged(sink).entries.size();
    if (sink.mode != "overwrite" && staged > 0)
        throw Error(fmt::format("database {}: an interrupted run over MPI ranks left {} entries staged in {}; "
                                "set mode to resume to complete the database with them, or to overwrite to "
                                "start afresh",
                                sink.database, staged, folder.string()));
    fs::remove_all(folder);
}

void merge(const DatabaseSink& sink) {
    const fs::path folder = stagingFolder(sink);
    if (!ownStagingFolder(sink)) return;
    Staged staged = readStaged(sink);
    if (!staged.entries.empty()) {
        CinemaWriterOptions o = staged.options;
        const CinemaWriterOptions mode = modeOptions(sink);
        o.overwrite = mode.overwrite;
        o.resume = mode.resume;
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
    writeFileAtomic((folder / kStagingMarker).string(),
                    "Darkroom stages the entries of " + sink.database + " here during a run over MPI ranks.\n");
}

}  // namespace

void prepareDatabase(const DatabaseSink& sink, bool overRanks) {
    withFileErrors([&] {
        prepare(sink);
        if (overRanks) beginStaging(sink);
    });
}

void mergeStagedEntries(const DatabaseSink& sink) {
    withFileErrors([&] { merge(sink); });
}

std::set<std::string> entriesKeptByResume(const DatabaseSink& sink) {
    return withFileErrors([&] { return keptEntries(sink); });
}

}  // namespace darkroom::cli
