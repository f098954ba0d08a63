// What `darkroom info` shows about a database: its rows, each column's type
// and range, and per FILE column the channels, size and camera of a product.
#include <darkroom/error.h>
#include <darkroom/framework/cinema/database.h>
#include <darkroom/framework/image_io.h>

#include <fmt/format.h>

#include <cmath>

namespace darkroom {

CinemaDescription CinemaDatabase::describe() const {
    CinemaDescription d;
    d.path = folder_;
    d.rows = rowCount();
    d.columns = columns_;
    d.warnings = warnings();
    for (std::size_t c : fileColumns()) {
        CinemaProductInfo p;
        p.column = columns_[c].name;
        // The first row that names a product stands for the column: products
        // of one column share size and channels in every database we know.
        std::size_t row = 0;
        while (row < rowCount() && cell(row, c).empty()) ++row;
        if (row == rowCount()) {
            p.error = "no row names a product";
        } else {
            p.path = productPath(row, p.column);
            try {
                const auto image = readImage(p.path);
                p.width = image->width();
                p.height = image->height();
                p.channels = image->channels();
                p.camera = image->metadata().camera;
            } catch (const std::exception& e) {
                p.error = e.what();
            }
        }
        d.products.push_back(std::move(p));
    }
    return d;
}

std::string formatDescription(const CinemaDescription& d) {
    std::string out = fmt::format("Cinema database {}\n  {} rows, {} columns\n", d.path, d.rows,
                                  d.columns.size());
    out += "columns:\n";
    for (const auto& c : d.columns) {
        std::string kind;
        if (c.isFile) {
            kind = fmt::format("file      {} distinct", c.distinct.size());
        } else if (c.numeric) {
            kind = fmt::format("number    {} .. {}, {} distinct", c.minimum, c.maximum, c.distinct.size());
        } else {
            kind = fmt::format("text      {} distinct", c.distinct.size());
            if (!c.distinct.empty() && c.distinct.size() <= 6) {
                kind += ":";
                for (const auto& v : c.distinct) kind += " " + (v.empty() ? std::string("(empty)") : v);
            }
        }
        if (c.missing) kind += fmt::format(", {} missing", c.missing);
        out += fmt::format("  {:<20} {}\n", c.name, kind);
    }
    if (d.products.empty()) out += "products: none (no FILE column)\n";
    for (const auto& p : d.products) {
        out += fmt::format("products of {}:\n", p.column);
        if (!p.error.empty()) {
            out += fmt::format("  could not read {}: {}\n", p.path.empty() ? "a product" : p.path, p.error);
            continue;
        }
        out += fmt::format("  size     {} x {}\n", p.width, p.height);
        std::string channels;
        for (const auto& ch : p.channels)
            channels += fmt::format("{}{} ({})", channels.empty() ? "" : ", ", ch.name, toString(ch.type));
        out += fmt::format("  channels {}\n", channels);
        if (p.camera) {
            const Camera& cam = *p.camera;
            const std::string lens = cam.projection == Camera::Projection::Perspective
                                         ? fmt::format("vertical field of view {} deg", cam.fovYDegrees)
                                         : fmt::format("view height {}", cam.viewHeight);
            out += fmt::format("  camera   {}, {}, position ({}, {}, {}), forward ({}, {}, {})\n",
                               toString(cam.projection), lens, cam.position.x, cam.position.y,
                               cam.position.z, cam.forward.x, cam.forward.y, cam.forward.z);
        } else {
            out += "  camera   none recorded\n";
        }
    }
    for (const auto& w : d.warnings) out += w.str() + "\n";
    return out;
}

}  // namespace darkroom
