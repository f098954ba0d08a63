#include "movie.h"

#include "h264_writer.h"
#include "movie_output.h"

#include <darkroom/atomic_file.h>
#include <darkroom/error.h>
#include <darkroom/data/cinema/database.h>
#include <darkroom/data/cinema/product.h>
#include <darkroom/srgb.h>
#include <darkroom/strings.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numeric>

namespace darkroom {

namespace fs = std::filesystem;

namespace {

// Rows in frame order: by the given columns, numbers ascending (NaN last),
// text in byte order; ties keep database order.
std::vector<std::size_t> frameOrder(const CinemaDatabase& db, std::vector<std::size_t> rows,
                                    const std::vector<std::size_t>& columns) {
    std::stable_sort(rows.begin(), rows.end(), [&](std::size_t a, std::size_t b) {
        for (std::size_t c : columns) {
            if (db.columns()[c].numeric) {
                const double x = db.number(a, c), y = db.number(b, c);
                if (std::isnan(x) || std::isnan(y)) {
                    if (std::isnan(x) != std::isnan(y)) return std::isnan(y);
                    continue;
                }
                if (x != y) return x < y;
            } else if (db.cell(a, c) != db.cell(b, c)) {
                return db.cell(a, c) < db.cell(b, c);
            }
        }
        return false;
    });
    return rows;
}

// Linear RGB(A) -> 8-bit sRGB RGB over `bg`, padded to even size by repeating
// the last column and row.
void toRgb8(const Buffer& b, const Color& bg, int width, int height, std::vector<std::uint8_t>& out) {
    const float* grey = b.hostFloat("Y");
    const float* c[3] = {b.hostFloat("R"), b.hostFloat("G"), b.hostFloat("B")};
    if (!(c[0] && c[1] && c[2])) c[0] = c[1] = c[2] = grey;
    const float* a = b.hostFloat("A");
    const float back[3] = {bg.r, bg.g, bg.b};
    out.resize(std::size_t(width) * std::size_t(height) * 3);
    for (int y = 0; y < height; ++y) {
        const int sy = std::min(y, b.height() - 1);
        for (int x = 0; x < width; ++x) {
            const std::size_t i = std::size_t(sy) * std::size_t(b.width()) + std::size_t(std::min(x, b.width() - 1));
            float alpha = a ? a[i] : 1.0f;
            if (!(alpha >= 0)) alpha = 0;
            alpha = std::min(alpha, 1.0f);
            for (int k = 0; k < 3; ++k) {
                float v = c[k][i];
                if (!std::isfinite(v)) v = 0, alpha = a ? 0 : alpha;
                const float linear = v * alpha + back[k] * (1 - alpha);
                const float e = std::clamp(linearToSrgb(std::clamp(linear, 0.0f, 1.0f)), 0.0f, 1.0f);
                out[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3 + std::size_t(k)] =
                    std::uint8_t(std::lround(e * 255.0f));
            }
        }
    }
}

}  // namespace

void Movie::execute(Context& ctx) {
    const std::string& given = ctx.getString(database_.name());
    if (given.empty()) throw Error("no database given; set 'database' to the Cinema database of the frames");
    std::string dbPath = ctx.resolveOutputPath(given);
    std::error_code ec;
    if (!fs::exists(dbPath, ec)) dbPath = ctx.resolveInputPath(given);
    const CinemaDatabase db = CinemaDatabase::open(dbPath);
    ctx.readsFile(db.csvPath());
    for (const auto& w : db.warnings()) ctx.warn(w.where + ": " + w.message);

    std::vector<std::size_t> rows;
    if (ctx.get(where_).empty()) {
        rows.resize(db.rowCount());
        std::iota(rows.begin(), rows.end(), std::size_t(0));
    } else {
        rows = db.selectWhere(ctx.get(where_));
    }
    if (rows.empty())
        throw Error("no entry of " + db.path() + (ctx.get(where_).empty() ? "" : " satisfies '" + ctx.get(where_) + "'") +
                    "; a movie needs at least one frame");
    std::vector<std::size_t> order;
    for (const std::string& name : splitList(ctx.get(orderBy_))) order.push_back(db.column(name));
    if (order.empty()) order = db.parameterColumns();
    rows = frameOrder(db, rows, order);

    const std::string file = ctx.get(file_);
    const std::string& out = ctx.getString(path_.name());
    if (out.empty()) throw Error("no movie file given; set 'path', e.g. movie.mp4");
    const std::string target = movie::resolveMoviePath(ctx, out);
    const fs::path parent = fs::path(target).parent_path();
    if (!parent.empty()) fs::create_directories(parent, ec);
    for (const std::string& stale : movie::removeStaleTemporaries(target))
        ctx.warn("removed " + stale + ", left by a run that was stopped while writing this movie");

    movie::H264Options options;
    options.frameRate = ctx.get(frameRate_);
    options.crf = int(ctx.get(quality_));
    options.preset = ctx.get(preset_);
    const Color background = ctx.get(background_);

    const std::string temporary = createTemporaryFile(target);
    try {
        std::unique_ptr<movie::H264Writer> writer;
        int width = 0, height = 0;
        std::vector<std::uint8_t> rgb;
        for (std::size_t k = 0; k < rows.size(); ++k) {
            if (ctx.cancelled()) {
                writer.reset();
                fs::remove(temporary, ec);
                return;
            }
            const std::string product = db.productPath(rows[k], file);
            ctx.readsFile(product);
            const auto image = readCinemaProduct(product);
            const bool colour = (image->hostFloat("R") && image->hostFloat("G") && image->hostFloat("B")) ||
                                image->hostFloat("Y");
            if (!colour)
                throw Error(product + " has no colour (R, G, B or Y); the movie needs pictures, e.g. the PNG "
                                      "products of CinemaWriter");
            if (!writer) {
                width = image->width() + image->width() % 2;
                height = image->height() + image->height() % 2;
                writer =
                    std::make_unique<movie::H264Writer>(movie::fileUrl(temporary), target, width, height, options);
            } else if (image->width() + image->width() % 2 != width || image->height() + image->height() % 2 != height) {
                throw Error(product + " is " + std::to_string(image->width()) + " x " + std::to_string(image->height()) +
                            " but the first frame (" + db.productPath(rows[0], file) + ") is " +
                            std::to_string(width) + " x " + std::to_string(height) + "; every frame needs one size");
            }
            toRgb8(*image, background, width, height, rgb);
            writer->addFrame(rgb.data(), std::size_t(width) * 3);
            ctx.progress(double(k + 1) / double(rows.size()));
        }
        writer->finish();
        writer.reset();
        commitFile(temporary, target);
    } catch (...) {
        fs::remove(temporary, ec);
        throw;
    }
}

}  // namespace darkroom
