#include <darkroom/workflows/staging.h>

#include <darkroom/error.h>
#include <darkroom/data/cinema/csv.h>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

namespace darkroom::workflows {

namespace fs = std::filesystem;

const char* const kStagingMarker = ".darkroom-staging";

namespace {

bool isRankFolderName(const std::string& name) {
    return name.size() > 5 && name.compare(0, 5, "rank-") == 0 &&
           std::all_of(name.begin() + 5, name.end(), [](char c) { return c >= '0' && c <= '9'; });
}

}  // namespace

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

namespace {

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

}  // namespace

StagedEntries readStagedDatabases(const std::string& folder) {
    StagedEntries out;
    std::vector<std::string> header;
    fs::path first;
    for (const auto& part : stagingDatabases(folder)) {
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

}  // namespace darkroom::workflows
