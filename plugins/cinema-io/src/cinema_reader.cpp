#include "cinema_reader.h"

#include <darkroom/error.h>
#include <darkroom/framework/cinema/composable.h>
#include <darkroom/framework/cinema/database.h>
#include <darkroom/framework/cinema/product.h>

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

PortList CinemaReader::ports() const {
    PortList p;
    p.pathIn("database", "", "The Cinema database: a .cdb folder or its data.csv");
    p.stringIn("parameters", "",
               "Which entry, as column=value pairs: 'phi=30, theta=45' (numbers snap to the "
               "nearest value present; unnamed columns take any value), or an SQL WHERE "
               "expression: 'phi > 0 AND theta = 0' (first matching row). Empty = the first row. "
               "In a composable image set the rows pick one layer ('object=000'), read whole");
    p.stringIn("file", "", "FILE column to read (e.g. FILE2); empty = the first FILE column");
    p.boolIn("strict", false, "Treat irregular rows in data.csv as errors instead of warnings");
    p.imageOut("image",
               "The entry's product: every EXR channel; linear R, G, B(, A) for 8-bit images; .npz "
               "members and .vti point arrays as channels; a composable image set's layer with "
               "depth as Z and colormap.<channel> attributes");
    return p;
}

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

void CinemaReader::execute(Context& ctx) {
    const std::string& given = ctx.getString("database");
    if (given.empty()) throw Error("CinemaReader: no database given; set 'database' to a .cdb folder");
    const auto db = open(ctx.resolveInputPath(given), ctx.getBool("strict"));
    for (const auto& w : db->warnings()) ctx.warn(w.where + ": " + w.message);
    const std::string& parameters = ctx.getString("parameters");
    const std::string& file = ctx.getString("file");
    Diagnostics notes;
    std::shared_ptr<WritableBuffer> image;
    if (isComposableImageSet(*db) && file.empty()) {
        // Every channel row of the chosen layer is merged into one buffer.
        const auto rows = parameters.empty() ? std::vector<std::size_t>{0} : db->selectWhere(parameters);
        if (ctx.cancelled()) return;
        image = readComposableRows(*db, rows, &notes);
    } else {
        std::size_t row = 0;
        if (CinemaDatabase::looksLikeSql(parameters)) {
            const auto rows = db->query(parameters);
            if (rows.empty())
                throw Error("no entry of Cinema database '" + db->path() + "' satisfies '" + parameters + "'");
            if (rows.size() > 1)
                ctx.warn(std::to_string(rows.size()) + " entries satisfy '" + parameters + "'; reading the first (" +
                         db->csvPath() + ":" + std::to_string(db->line(rows[0])) + ")");
            row = rows[0];
        } else {
            const auto match = db->find(parameters);
            for (const auto& note : match.notes) ctx.warn(note);
            row = match.row;
        }
        if (ctx.cancelled()) return;
        image = readCinemaProduct(db->productPath(row, file), &notes);
    }
    for (const auto& n : notes) ctx.warn(n.where + ": " + n.message);
    ctx.progress(1.0);
    ctx.setOutput("image", BufferPtr(std::move(image)));
}

}  // namespace darkroom
