// Reading one composable-image-set channel file by the CIS convention ([x][y]
// arrays, CISOrigin) and reporting every way it can disagree with data.csv.
#include "cis_channel.h"

#include <darkroom/error.h>
#include <darkroom/data/cinema/product.h>
#include <darkroom/data/formats/npy.h>
#include <darkroom/strings.h>

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace darkroom::cis {

namespace {

std::string upper(std::string s) {
    for (char& c : s) c = char(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

bool isNpz(const std::string& path) {
    std::string e = std::filesystem::path(path).extension().string();
    for (char& c : e) c = char(std::tolower(static_cast<unsigned char>(c)));
    return e == ".npz";
}

std::string shapeText(const std::vector<std::size_t>& shape) {
    std::string s = "(";
    for (std::size_t i = 0; i < shape.size(); ++i) s += (i ? ", " : "") + std::to_string(shape[i]);
    return s + (shape.size() == 1 ? ",)" : ")");
}

// Which columns gave the layer's size: its own, or the image's by default.
std::string sizeColumns(const CinemaDatabase& db) {
    if (db.findColumn("CISLayerWidth") && db.findColumn("CISLayerHeight")) return "CISLayerWidth/CISLayerHeight";
    return "CISImageWidth/CISImageHeight (the layer's size by default)";
}

// The member holding the channel: 'data' (what cinemasci reads), else the only
// member (with a warning), else an error listing the members.
const NpyArray& channelMember(const std::vector<NpyArray>& members, const std::string& path,
                              const CinemaDatabase& db, const CisChannel& ch, Diagnostics* warnings) {
    for (const auto& m : members)
        if (m.name == "data") {
            if (members.size() > 1 && warnings)
                warnings->push_back({Diagnostic::Severity::Warning, path,
                                     fmt::format("{} members; only 'data' is read as channel {} ({}:{})",
                                                 members.size(), ch.bufferName(), db.csvPath(), db.line(ch.row)),
                                     {}});
            return m;
        }
    if (members.size() == 1) {
        if (warnings)
            warnings->push_back({Diagnostic::Severity::Warning, path,
                                 fmt::format("its only member is '{}.npy', not 'data.npy' as the CIS writers name "
                                             "it; read as channel {} ({}:{} CISChannel {})",
                                             members.front().name, ch.bufferName(), db.csvPath(), db.line(ch.row),
                                             ch.channel),
                                 {}});
        return members.front();
    }
    std::string names;
    for (const auto& m : members) names += (names.empty() ? "'" : ", '") + m.name + ".npy'";
    throw Error(fmt::format("{}: no member 'data.npy' holds channel {} ({}:{} CISChannel {}); expected one "
                            "member named 'data', found {}",
                            path, ch.bufferName(), db.csvPath(), db.line(ch.row), ch.channel, names));
}

// CISChannelVarType (string, int, float; float by default) against the dtype.
void checkType(const NpyArray& a, const std::string& where, const CinemaDatabase& db, const CisChannel& ch,
               Diagnostics* warnings) {
    const char kind = a.descr.size() > 1 ? a.descr[1] : '?';
    const bool isFloat = kind == 'f', isInteger = kind == 'i' || kind == 'u' || kind == 'b';
    const auto c = db.findColumn("CISChannelVarType");
    const std::string stated = c ? std::string(trimBlanks(db.cell(ch.row, *c))) : std::string();
    if (stated.empty()) {
        if (!isFloat && warnings)
            warnings->push_back({Diagnostic::Severity::Warning, where,
                                 fmt::format("dtype '{}' is not a float type, the CIS default where "
                                             "CISChannelVarType is not given ({}:{}); values are converted to "
                                             "float32",
                                             a.descr, db.csvPath(), db.line(ch.row)),
                                 {}});
        return;
    }
    const std::string type = upper(stated);
    if (type == "FLOAT" && isFloat) return;
    if (type == "INT" && isInteger) return;
    if (type != "FLOAT" && type != "INT")
        throw Error(fmt::format("{}:{}: CISChannelVarType is '{}'; Darkroom reads 'float' or 'int' channels "
                                "(the CIS types are string, int and float)",
                                db.csvPath(), db.line(ch.row), stated));
    throw Error(fmt::format("{}: dtype '{}', but {}:{} CISChannelVarType says '{}' (expected a{} dtype such as "
                            "'{}')",
                            where, a.descr, db.csvPath(), db.line(ch.row), stated,
                            type == "FLOAT" ? " float" : "n integer", type == "FLOAT" ? "<f4" : "<i4"));
}

}  // namespace

std::string parseOrigin(const CinemaDatabase& db, std::size_t row) {
    const auto c = db.findColumn("CISOrigin");
    if (!c) return "UL";
    const std::string v = upper(std::string(trimBlanks(db.cell(row, *c))));
    if (v.empty()) return "UL";
    if (v == "UL" || v == "UR" || v == "LL" || v == "LR") return v;
    throw Error(fmt::format("{}:{}: CISOrigin is '{}'; expected UL, UR, LL or LR (the corner of pixel (0, 0))",
                            db.csvPath(), db.line(row), db.cell(row, *c)));
}

std::vector<float> readChannelValues(const CinemaDatabase& db, const CisImage& image, const CisLayer& layer,
                                     const CisChannel& ch, Diagnostics* warnings) {
    (void)image;
    const std::string path = db.productPath(ch.row);
    const std::size_t W = std::size_t(layer.width), H = std::size_t(layer.height);
    if (!isNpz(path)) {
        // Not a CIS .npz (the specification allows only those): an image file,
        // whose rows run top to bottom as in any picture. Stored [x][y] here.
        const auto product = readCinemaProduct(path, warnings);
        if (std::size_t(product->width()) != W || std::size_t(product->height()) != H)
            throw Error(fmt::format("{}: {} x {} pixels, but {}:{} {} say layer {} is {} x {}", path,
                                    product->width(), product->height(), db.csvPath(), db.line(ch.row),
                                    sizeColumns(db), layer.id, W, H));
        const auto names = product->channelNames();
        const float* src = names.empty() ? nullptr : product->hostFloat(names.front());
        if (!src) throw Error(fmt::format("{}: expected a float channel for {}", path, ch.bufferName()));
        std::vector<float> out(W * H);
        const bool up = image.origin == "LL" || image.origin == "LR";
        const bool right = image.origin == "UR" || image.origin == "LR";
        for (std::size_t row = 0; row < H; ++row)
            for (std::size_t col = 0; col < W; ++col) {
                const std::size_t x = right ? W - 1 - col : col, y = up ? H - 1 - row : row;
                out[x * H + y] = src[row * W + col];
            }
        return out;
    }
    const auto members = readNpz(path);
    return checkedMember(db, layer, ch, path, members, warnings).values;  // C order of (W, H): x * H + y
}

const NpyArray& checkedMember(const CinemaDatabase& db, const CisLayer& layer, const CisChannel& ch,
                              const std::string& path, const std::vector<NpyArray>& members, Diagnostics* warnings) {
    const std::size_t W = std::size_t(layer.width), H = std::size_t(layer.height);
    if (members.empty()) throw Error(fmt::format("{}: the archive holds no .npy member", path));
    const NpyArray& a = channelMember(members, path, db, ch, warnings);
    const std::string where = path + ":" + a.name + ".npy";
    checkType(a, where, db, ch, warnings);
    const std::vector<std::size_t> expected{W, H};
    if (a.shape != expected) {
        std::string hint;
        if (a.shape.size() == 2 && a.shape[0] == H && a.shape[1] == W)
            hint = "; it is (height, width), rows first: the CIS convention indexes channels [x][y]";
        else if (a.shape.size() == 3 && a.shape[0] == W && a.shape[1] == H)
            hint = fmt::format("; a channel holds one value per pixel, not {}", a.shape[2]);
        throw Error(fmt::format("{}: shape {}, but {}:{} {} say layer {} is {} x {} (expected shape {}: [x][y], "
                                "width first){}",
                                where, shapeText(a.shape), db.csvPath(), db.line(ch.row), sizeColumns(db), layer.id,
                                W, H, shapeText(expected), hint));
    }
    return a;
}

void placeLayer(const std::vector<float>& values, const CisImage& image, const CisLayer& layer, float* plane) {
    const std::size_t W = std::size_t(image.width), H = std::size_t(image.height);
    const std::size_t w = std::size_t(layer.width), h = std::size_t(layer.height);
    const bool fromBottom = image.origin == "LL" || image.origin == "LR";
    const bool fromRight = image.origin == "UR" || image.origin == "LR";
    for (std::size_t x = 0; x < w; ++x) {
        // Image coordinates counted from the origin corner, then to columns and rows.
        const std::size_t ix = std::size_t(layer.offsetX) + x;
        const std::size_t col = fromRight ? W - 1 - ix : ix;
        const float* src = values.data() + x * h;
        for (std::size_t y = 0; y < h; ++y) {
            const std::size_t iy = std::size_t(layer.offsetY) + y;
            const std::size_t row = fromBottom ? H - 1 - iy : iy;
            plane[row * W + col] = src[y];
        }
    }
}

}  // namespace darkroom::cis
