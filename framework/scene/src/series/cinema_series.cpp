// A series named by a Cinema database whose FILE column lists meshes or
// volumes (as TTK's example databases hold a simulation's steps): one step
// per row, its parameter columns carried into the captured database.
#include "series_sources.h"

#include <darkroom/error.h>
#include <darkroom/strings.h>
#include <darkroom/data/cinema/database.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace darkroom::series {

namespace {

bool isTimeColumn(const std::string& name) {
    std::string lower = name;
    for (char& c : lower) c = char(std::tolower(static_cast<unsigned char>(c)));
    return lower == "time";
}

// The one FILE column (or the one named FILE among several).
std::size_t meshColumn(const CinemaDatabase& db) {
    const std::vector<std::size_t> files = db.fileColumns();
    if (files.size() == 1) return files.front();
    for (std::size_t c : files)
        if (db.columns()[c].name == "FILE") return c;
    throw InputError(db.csvPath() + ": " +
                     (files.empty() ? std::string("no FILE column")
                                    : std::to_string(files.size()) + " FILE columns and none named FILE") +
                     "; expected one FILE column listing the mesh or volume file of each time step");
}

}  // namespace

ObjectSeries cinemaSeries(const std::string& path) {
    const CinemaDatabase db = CinemaDatabase::open(path);
    const std::size_t fileColumn = meshColumn(db);
    ObjectSeries out;
    std::optional<std::size_t> timeColumn;
    const std::vector<std::size_t> parameters = db.parameterColumns();
    for (std::size_t c : parameters) {
        out.columns.push_back(db.columns()[c].name);
        if (isTimeColumn(db.columns()[c].name) && db.columns()[c].numeric) timeColumn = c;
    }
    const std::string& fileName = db.columns()[fileColumn].name;
    for (std::size_t row = 0; row < db.rowCount(); ++row) {
        SeriesItem item;
        if (timeColumn) item.time = db.number(row, *timeColumn);
        for (std::size_t c : parameters)
            item.values.push_back(db.columns()[c].numeric ? CinemaValue(db.number(row, c)) : CinemaValue(db.cell(row, c)));
        item.file = db.productPath(row, fileName);
        std::error_code ec;
        if (!std::filesystem::is_regular_file(item.file, ec))
            throw InputError(db.csvPath() + ":" + std::to_string(db.line(row)) + ": " + fileName + " names '" +
                             item.file + "', which does not exist; expected a mesh or volume file");
        out.items.push_back(std::move(item));
    }
    if (out.items.empty()) throw InputError(db.csvPath() + ": the database has no rows; expected one per time step");
    if (timeColumn)
        std::stable_sort(out.items.begin(), out.items.end(),
                         [](const SeriesItem& a, const SeriesItem& b) { return *a.time < *b.time; });
    return out;
}

}  // namespace darkroom::series
