#include "series_staging.h"

#include <darkroom/atomic_file.h>
#include <darkroom/error.h>
#include <darkroom/workflows/staging.h>
#include <darkroom/workflows/written_databases.h>

#include <filesystem>

namespace darkroom::workflows::detail {

namespace fs = std::filesystem;

namespace {

std::string databasePath(const SceneCapture& r) {
    std::string p = r.output;
    while (p.size() > 1 && p.back() == '/') p.pop_back();
    return p;
}

fs::path stagingFolderOf(const SceneCapture& r) { return databasePath(r) + ".staging"; }

// Whether the staging folder exists; refused when Darkroom did not make it
// (no marker inside): someone else's folder is neither read nor removed.
bool ownStagingFolder(const SceneCapture& r) {
    const fs::path folder = stagingFolderOf(r);
    std::error_code ec;
    const auto st = fs::symlink_status(folder, ec);
    if (!fs::exists(st)) return false;
    if (!fs::is_directory(st) || !fs::is_regular_file(fs::symlink_status(folder / kStagingMarker, ec)))
        throw InputError(folder.string() + " exists and Darkroom did not make it (no " + kStagingMarker +
                         " inside); a time series captured over MPI ranks stages its steps there, so move it away "
                         "(nothing in it was touched)");
    return true;
}

// The staged entries adopted into the database, then the staging folder removed.
void adoptStaged(const SceneCapture& r, bool resume) {
    StagedEntries staged = readStagedDatabases(stagingFolderOf(r).string());
    if (!staged.entries.empty()) {
        CinemaWriterOptions o = staged.options;
        o.overwrite = !resume && r.overwrite;
        o.resume = resume;
        CinemaWriter w(databasePath(r), staged.columns, o);
        // As captureEntries does alone: a resumed database keeps the entries it has.
        std::vector<CinemaStagedEntry> adopt;
        for (auto& e : staged.entries)
            if (!resume || !w.hasEntry(e.parameters)) adopt.push_back(std::move(e));
        w.adoptEntries(adopt);
        w.finish();
    }
    fs::remove_all(stagingFolderOf(r));
}

template <class F>
auto asInputError(F&& f) {
    try {
        return f();
    } catch (const fs::filesystem_error& e) {
        throw InputError(e.what());
    } catch (const InputError&) {
        throw;
    } catch (const Error& e) {
        throw InputError(e.what());
    }
}

}  // namespace

std::string seriesStagingDatabase(const SceneCapture& r, int rank) {
    return fs::absolute(stagingFolderOf(r) / ("rank-" + std::to_string(rank))).lexically_normal().string();
}

void prepareSeriesStaging(const SceneCapture& r) {
    asInputError([&] {
        CinemaWriterOptions mode;
        mode.overwrite = r.overwrite;
        mode.resume = r.resume;
        CinemaWriter::check(databasePath(r), mode);
        const fs::path folder = stagingFolderOf(r);
        if (ownStagingFolder(r)) {
            // A staging database still locked is being written by a run now.
            CinemaWriterOptions locked;
            locked.resume = true;
            for (const auto& part : stagingDatabases(folder)) CinemaWriter::check(part.string(), locked);
            const std::size_t staged = readStagedDatabases(folder.string()).entries.size();
            if (r.resume) adoptStaged(r, true);
            else if (!r.overwrite && staged > 0)
                throw InputError("database " + databasePath(r) + ": an interrupted capture over MPI ranks left " +
                                 std::to_string(staged) + " entries staged in " + folder.string() +
                                 "; use --resume to complete the database with them, or --overwrite to start afresh");
            fs::remove_all(folder);
        }
        fs::create_directories(folder);
        writeFileAtomic((folder / kStagingMarker).string(),
                        "Darkroom stages the steps of " + databasePath(r) +
                            " here while a time series is captured over MPI ranks.\n");
    });
}

std::set<std::string> seriesEntriesKept(const SceneCapture& r) {
    if (!r.resume) return {};
    DatabaseSink sink;
    sink.database = databasePath(r);
    sink.mode = "resume";
    return asInputError([&] { return entriesKeptByResume(sink); });
}

void mergeSeriesStaging(const SceneCapture& r) {
    try {
        adoptStaged(r, r.resume);
    } catch (const fs::filesystem_error& e) {
        throw Error(e.what());
    }
}

}  // namespace darkroom::workflows::detail
