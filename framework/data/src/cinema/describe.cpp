// What `darkroom info` shows about a database: its rows, each column's type
// and range, and per FILE column the channels, size and camera of a product.
#include <darkroom/error.h>
#include <darkroom/layers.h>
#include <darkroom/data/cinema/composable.h>
#include <darkroom/data/cinema/consistency.h>
#include <darkroom/data/cinema/database.h>
#include <darkroom/data/cinema/product.h>
#include <darkroom/data/formats/npy.h>
#include <darkroom/data/formats/point_list.h>

#include <filesystem>

#include <fmt/format.h>

#include <cctype>
#include <cmath>

namespace darkroom {

namespace {

bool hasExtension(const std::string& path, const char* ext) {
    std::string e = std::filesystem::path(path).extension().string();
    for (char& c : e) c = char(std::tolower(static_cast<unsigned char>(c)));
    return e == ext;
}

// .npz: the members' dtypes and shapes from their headers, without reading the data.
// A composable image set's arrays are [x][y] (shape = width, height); other
// .npz products are (rows, columns) like any numpy image.
void describeNpz(CinemaProductInfo& p, bool composable) {
    for (const auto& a : readNpzHeaders(p.path)) {
        std::string shape;
        for (std::size_t d : a.shape) shape += (shape.empty() ? "" : ", ") + std::to_string(d);
        p.details.push_back(fmt::format("{}.npy: {} ({}){}", a.name, a.descr, shape,
                                        a.fortranOrder ? " Fortran order" : ""));
        p.channels.push_back({a.name, ChannelType::Float32});
        if (a.shape.size() >= 2 && p.width == 0) {
            p.width = int(a.shape[composable ? 0 : 1]);
            p.height = int(a.shape[composable ? 1 : 0]);
        }
    }
}

// "layers   4 (Z, N, objectId, height per layer)" for a G-buffer with
// layer<k>.Z channels (darkroom/layers.h); nothing for an ordinary one.
void describeLayers(CinemaProductInfo& p) {
    int count = 1;
    auto has = [&p](const std::string& name) {
        for (const auto& ch : p.channels)
            if (ch.name == name) return true;
        return false;
    };
    while (has(layers::channel("Z", count))) ++count;
    if (count == 1) return;
    std::string perLayer;
    bool normals = false;
    for (const auto& ch : p.channels) {
        const auto [layer, name] = layers::parse(ch.name);
        if (layer != 0) continue;
        if (name == "N.x" || name == "N.y" || name == "N.z") {
            if (normals) continue;
            normals = true;
            perLayer += std::string(perLayer.empty() ? "" : ", ") + "N";
            continue;
        }
        perLayer += (perLayer.empty() ? "" : ", ") + name;
    }
    p.details.push_back(fmt::format("layers   {} ({} per layer; layer<k>.<channel> for k >= 1)", count, perLayer));
}

}  // namespace

CinemaDescription CinemaDatabase::describe() const {
    CinemaDescription d;
    d.path = folder_;
    d.rows = rowCount();
    d.columns = columns_;
    d.warnings = warnings();
    // Every product against data.csv (headers only), so one odd file among thousands is named.
    for (auto& x : checkProductFiles(*this)) d.warnings.push_back(std::move(x));
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
                if (const auto geometry = geometryProduct(p.path)) {
                    p.geometry = geometry->what;
                    p.geometryAdvice = geometry->advice;
                } else if (hasExtension(p.path, ".npz")) {
                    describeNpz(p, isComposableImageSet(*this));
                } else if (hasExtension(p.path, ".csv")) {
                    const PointList points = readPointListCsv(p.path);
                    std::string columns = "x, y, z";
                    if (!points.radii.empty()) columns += ", radius";
                    for (const auto& f : points.fields) columns += ", " + f.name;
                    p.pointList = true;
                    p.details.push_back(fmt::format("point list: {} points, columns {}", points.size(), columns));
                } else {
                    Diagnostics notes;
                    const auto image = readCinemaProduct(p.path, &notes);
                    p.width = image->width();
                    p.height = image->height();
                    p.channels = image->channels();
                    p.camera = image->metadata().camera;
                    describeLayers(p);
                    for (const auto& n : notes) p.details.push_back(n.message);
                }
            } catch (const std::exception& e) {
                p.error = e.what();
            }
        }
        d.products.push_back(std::move(p));
    }
    if (isComposableImageSet(*this)) {
        try {
            for (const auto& img : composableImages(*this)) {
                d.composable.push_back(fmt::format("image {} ({} x {}), {} layers, origin {}{}", img.id, img.width,
                                                   img.height, img.layers.size(), img.origin,
                                                   img.originStated ? "" : " (assumed: no CISOrigin column)"));
                for (const auto& l : img.layers) {
                    std::string channels;
                    for (const auto& ch : l.channels) {
                        channels += (channels.empty() ? "" : ", ") + ch.bufferName();
                        if (ch.isDepth) channels += " (from " + ch.variable + ")";
                        if (!ch.colormap.empty()) channels += " (colour map " + ch.colormap + ")";
                    }
                    d.composable.push_back(fmt::format("  layer {} [{}] {} x {} at ({}, {}): {}", l.id, l.parameters,
                                                       l.width, l.height, l.offsetX, l.offsetY, channels));
                }
            }
        } catch (const std::exception& e) {
            d.composable.push_back(std::string("could not group the composable image set: ") + e.what());
        }
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
        if (p.pointList) {
            for (const auto& line : p.details) out += fmt::format("  {}\n", line);
            continue;
        }
        if (!p.geometry.empty()) {
            out += fmt::format("  not images: {} is {}\n  {}\n", p.path, p.geometry, p.geometryAdvice);
            continue;
        }
        out += fmt::format("  size     {} x {}\n", p.width, p.height);
        std::string channels;
        for (const auto& ch : p.channels)
            channels += fmt::format("{}{} ({})", channels.empty() ? "" : ", ", ch.name, toString(ch.type));
        out += fmt::format("  channels {}\n", channels);
        for (const auto& line : p.details) out += fmt::format("  {}\n", line);
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
    if (!d.composable.empty()) {
        out += "composable image set (each layer reads as one buffer; depth as Z):\n";
        for (const auto& line : d.composable) out += "  " + line + "\n";
    }
    for (const auto& w : d.warnings) out += w.str() + "\n";
    return out;
}

}  // namespace darkroom
