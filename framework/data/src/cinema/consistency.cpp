// Every product of a database checked against data.csv from its header alone:
// existence, Spec D size and channels per FILE column, CIS shapes and dtypes.
#include "cis_channel.h"

#include "../io/image_header.h"

#include <darkroom/error.h>
#include <darkroom/data/cinema/composable.h>
#include <darkroom/data/cinema/consistency.h>
#include <darkroom/data/cinema/product.h>
#include <darkroom/data/formats/npy.h>

#include <fmt/format.h>

#include <cctype>
#include <filesystem>
#include <map>
#include <optional>

namespace darkroom {

namespace fs = std::filesystem;

namespace {

std::string extensionOf(const std::string& path) {
    std::string e = fs::path(path).extension().string();
    for (char& c : e) c = char(std::tolower(static_cast<unsigned char>(c)));
    return e;
}

struct Header {
    int width = 0, height = 0;
    std::vector<std::string> channels;
};

// Size and channel names without the pixels; nullopt for formats whose header
// we do not read here (.vti: read whole by the reader, which checks it) and for
// products that are not images.
std::optional<Header> readHeader(const std::string& path) {
    const std::string ext = extensionOf(path);
    // .csv: a point list (scene/point_list.h), no pixels to compare; a mesh
    // or a volume neither (describe() says what to do with it).
    if (ext == ".vti" || ext == ".csv" || geometryProduct(path)) return std::nullopt;
    Header h;
    if (ext == ".npz") {
        // Outside a composable image set an .npz is a numpy image: (rows, columns).
        for (const auto& a : readNpzHeaders(path)) {
            if (a.shape.size() >= 2 && h.width == 0) h.height = int(a.shape[0]), h.width = int(a.shape[1]);
            h.channels.push_back(a.name);
        }
        return h;
    }
    const io::ImageHeader image = io::readImageHeader(path);
    h.width = image.width;
    h.height = image.height;
    for (const auto& c : image.channels) h.channels.push_back(c.name);
    return h;
}

std::string joined(const std::vector<std::string>& v) {
    std::string s;
    for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
    return s;
}

void error(Diagnostics& out, const std::string& where, const std::string& message) {
    out.push_back({Diagnostic::Severity::Error, where, message, {}});
}

void checkSpecD(const CinemaDatabase& db, std::size_t column, Diagnostics& out) {
    const std::string& name = db.columns()[column].name;
    std::optional<Header> first;
    std::string firstPath;
    int firstLine = 0;
    for (std::size_t r = 0; r < db.rowCount(); ++r) {
        if (db.cell(r, column).empty()) continue;
        const std::string path = db.productPath(r, name);
        std::error_code ec;
        if (!fs::is_regular_file(path, ec)) continue;  // reported by the existence check
        std::optional<Header> h;
        try {
            h = readHeader(path);
        } catch (const std::exception& e) {
            error(out, fmt::format("{}:{}", db.csvPath(), db.line(r)),
                  fmt::format("{} {}: {}", name, db.cell(r, column), e.what()));
            continue;
        }
        if (!h) continue;
        if (!first) {
            first = h, firstPath = path, firstLine = db.line(r);
            continue;
        }
        if (h->width != first->width || h->height != first->height)
            out.push_back({Diagnostic::Severity::Warning, path,
                           fmt::format("{} x {} pixels, but the first product of column {} ({}, {}:{}) is {} x {}; "
                                       "expected one size per FILE column",
                                       h->width, h->height, name, firstPath, db.csvPath(), firstLine, first->width,
                                       first->height),
                           {}});
        else if (h->channels != first->channels)
            out.push_back({Diagnostic::Severity::Warning, path,
                           fmt::format("channels {}, but the first product of column {} ({}, {}:{}) has {}; "
                                       "expected the same channels in every product of a FILE column",
                                       joined(h->channels), name, firstPath, db.csvPath(), firstLine,
                                       joined(first->channels)),
                           {}});
    }
}

void checkComposable(const CinemaDatabase& db, Diagnostics& out) {
    std::vector<CisImage> images;
    try {
        images = composableImages(db);
    } catch (const std::exception& e) {
        error(out, db.csvPath(), e.what());
        return;
    }
    for (const auto& image : images)
        for (const auto& layer : image.layers)
            for (const auto& ch : layer.channels) {
                const std::string path = db.productPath(ch.row);
                if (!fs::exists(path)) continue;  // reported by the existence check
                if (extensionOf(path) != ".npz") {
                    out.push_back({Diagnostic::Severity::Warning, path,
                                   fmt::format("channel {} of layer {} ({}:{}) is not an .npz; the CIS "
                                               "specification stores channels as .npz, so this one is read as a "
                                               "picture, rows top to bottom",
                                               ch.bufferName(), layer.id, db.csvPath(), db.line(ch.row)),
                                   {}});
                    continue;
                }
                try {
                    Diagnostics notes;
                    cis::checkedMember(db, layer, ch, path, readNpzHeaders(path), &notes);
                    out.insert(out.end(), notes.begin(), notes.end());
                } catch (const std::exception& e) {
                    error(out, "", e.what());
                }
            }
}

}  // namespace

Diagnostics checkProductFiles(const CinemaDatabase& db) {
    Diagnostics out;
    const auto files = db.fileColumns();
    for (std::size_t c : files)
        for (std::size_t r = 0; r < db.rowCount(); ++r) {
            const std::string& cell = db.cell(r, c);
            if (cell.empty()) continue;
            const std::string path = db.productPath(r, db.columns()[c].name);
            std::error_code ec;
            if (!fs::is_regular_file(path, ec))
                error(out, fmt::format("{}:{}", db.csvPath(), db.line(r)),
                      fmt::format("{} names '{}', which {}; expected a product file relative to {}",
                                  db.columns()[c].name, cell, fs::exists(path, ec) ? "is not a file" : "does not exist",
                                  db.path()));
        }
    if (isComposableImageSet(db)) {
        checkComposable(db, out);
    } else {
        for (std::size_t c : files) checkSpecD(db, c, out);
    }
    return out;
}

}  // namespace darkroom
