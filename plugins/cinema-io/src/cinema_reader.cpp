#include "cinema_reader.h"

#include <darkroom/error.h>
#include <darkroom/data/cinema/composable.h>
#include <darkroom/data/cinema/database.h>
#include <darkroom/data/cinema/product.h>
#include <darkroom/data/cinema/row.h>

#include <filesystem>

namespace darkroom {

namespace fs = std::filesystem;

struct CinemaReader::Cache {
    std::string path;
    bool strict = false;
    fs::file_time_type modified;
    std::uintmax_t size = 0;
    std::shared_ptr<const CinemaDatabase> db;
};

CinemaReader::CinemaReader() : cache_(std::make_unique<Cache>()) {}
CinemaReader::~CinemaReader() = default;

std::shared_ptr<const CinemaDatabase> CinemaReader::open(const std::string& path, bool strict) {
    std::error_code ec;
    const fs::path csv = fs::is_directory(path, ec) ? fs::path(path) / "data.csv" : fs::path(path);
    const auto modified = fs::last_write_time(csv, ec);
    const auto size = ec ? 0 : fs::file_size(csv, ec);
    std::lock_guard<std::mutex> g(mutex_);
    if (!cache_->db || cache_->path != path || cache_->strict != strict || ec ||
        cache_->modified != modified || cache_->size != size) {
        cache_->db = std::make_shared<const CinemaDatabase>(CinemaDatabase::open(path, {strict}));
        cache_->path = path;
        cache_->strict = strict;
        cache_->modified = modified;
        cache_->size = size;
    }
    return cache_->db;
}

std::size_t CinemaReader::rowOf(const CinemaDatabase& db, const std::string& parameters, Context& ctx) const {
    if (CinemaDatabase::looksLikeSql(parameters)) {
        const auto rows = db.query(parameters);
        if (rows.empty()) throw Error("no entry of Cinema database '" + db.path() + "' satisfies '" + parameters + "'");
        if (rows.size() > 1)
            ctx.warn(std::to_string(rows.size()) + " entries satisfy '" + parameters + "'; reading the first (" +
                     db.csvPath() + ":" + std::to_string(db.line(rows[0])) + ")");
        return rows[0];
    }
    const auto match = db.find(parameters);
    for (const auto& note : match.notes) ctx.warn(note);
    return match.row;
}

void CinemaReader::execute(Context& ctx) {
    const std::string path = ctx.get(database_);
    if (path.empty()) throw Error("no database given; set 'database' to a .cdb folder");
    const auto db = open(path, ctx.get(strict_));
    // The cache key: data.csv and the product read, by modification time and size.
    ctx.readsFile(db->csvPath());
    for (const auto& w : db->warnings()) ctx.warn(w.where + ": " + w.message);
    const std::int64_t entry = ctx.get(entry_);
    if (entry >= 0 && std::uint64_t(entry) >= db->rowCount())
        throw Error("entry " + std::to_string(entry) + " is past the last row of Cinema database '" + db->path() +
                    "' (" + std::to_string(db->rowCount()) + " rows, numbered from 0)");
    const std::string& parameters = ctx.get(parameters_);
    const std::string& file = ctx.get(file_);
    Diagnostics notes;
    std::shared_ptr<WritableBuffer> image;
    std::size_t rowRead = 0;
    if (isComposableImageSet(*db) && file.empty()) {
        // Every channel row of the chosen layer is merged into one buffer.
        const auto rows = entry >= 0            ? std::vector<std::size_t>{std::size_t(entry)}
                          : parameters.empty() ? std::vector<std::size_t>{0}
                                               : db->selectWhere(parameters);
        for (const std::size_t r : rows) ctx.readsFile(db->productPath(r, ""));
        if (!rows.empty()) rowRead = rows.front();
        image = readComposableRows(*db, rows, &notes);
    } else {
        rowRead = entry >= 0 ? std::size_t(entry) : rowOf(*db, parameters, ctx);
        const std::string product = db->productPath(rowRead, file);
        ctx.readsFile(product);
        image = readCinemaProduct(product, &notes);
    }
    for (const auto& n : notes) ctx.warn(n.where + ": " + n.message);
    // What "the whole database" means downstream (ColorMapping's range).
    if (const std::string& selection = ctx.get(selection_); !selection.empty())
        image->metadata().attributes["run.selection"] = selection;
    ctx.progress(1.0);
    ctx.set(result_, image);
    ctx.set(row_, Value(cinemaRow(*db, rowRead)));
}

}  // namespace darkroom
