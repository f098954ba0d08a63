#pragma once
// Staging databases: under `mpirun -np N darkroom run --foreach`, each rank
// writes the entries it shades into <database>.staging/rank-<k>, and the
// lead adopts them into the database at the end (docs/scale-out.md). What
// is read from a staging folder is checked as input from outside: only
// plain files inside their rank's folder are adopted, never a link or a
// path leading elsewhere (S2 of issue 26; tests/fuzz/harnesses/staged.cpp).
#include <darkroom/export.h>
#include <darkroom/data/cinema/writer.h>

#include <filesystem>
#include <string>
#include <vector>

namespace darkroom::workflows {

// The file that marks a staging folder as Darkroom's: without it, the
// folder is someone else's and is neither read nor removed.
DARKROOM_API extern const char* const kStagingMarker;

// What the staging databases hold complete, in the order of their folders
// and rows, with the columns and file naming they were written with.
struct StagedEntries {
    std::vector<std::string> columns;
    CinemaWriterOptions options;  // product extension, attachment columns, the recorded origin
    std::vector<CinemaStagedEntry> entries;
};

// The staging databases of `folder`: real folders named rank-<k> (never
// links), sorted.
DARKROOM_API std::vector<std::filesystem::path> stagingDatabases(const std::filesystem::path& folder);

// Reads every staging database's data.csv (strictly). Entries whose files
// are not all there are left out (shaded again). Throws darkroom::Error
// naming the file when a data.csv has no FILE column, when two staging
// databases have different columns, or when a FILE cell is not a plain file
// name inside its staging database or names a link or a folder.
DARKROOM_API StagedEntries readStagedDatabases(const std::string& folder);

}  // namespace darkroom::workflows
