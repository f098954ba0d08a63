// Composable image sets: grouping rows into images/layers/channels and
// assembling one layer as a buffer with Darkroom's depth convention.
#include "cis_channel.h"

#include <darkroom/error.h>
#include <darkroom/data/cinema/composable.h>

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <limits>
#include <set>

namespace darkroom {

namespace fs = std::filesystem;

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

std::string lower(std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

bool isCisColumn(const std::string& name) { return name.rfind("CIS", 0) == 0; }

const std::string& cellOf(const CinemaDatabase& db, std::size_t row, const char* column) {
    static const std::string empty;
    const auto c = db.findColumn(column);
    return c ? db.cell(row, *c) : empty;
}

// A size or offset cell: a non-negative integer (written "1024" or "1024.0").
int integerCell(const CinemaDatabase& db, std::size_t row, const char* column, int fallback, bool positive) {
    const auto c = db.findColumn(column);
    if (!c || db.cell(row, *c).empty()) return fallback;
    const double v = db.number(row, *c);
    if (!(v >= (positive ? 1 : 0)) || v != std::floor(v) || v > (1 << 20))
        throw Error(fmt::format("{}:{}: {} is '{}'; expected a {} integer", db.csvPath(), db.line(row), column,
                                db.cell(row, *c), positive ? "positive" : "non-negative"));
    return int(v);
}

// Every row of an image (layer) must repeat its size and offsets: a row that
// disagrees is reported, never resolved by taking the first.
void sameAsEarlier(const CinemaDatabase& db, std::size_t row, const char* column, int earlier, int fallback,
                   bool positive, const std::string& what) {
    const int v = integerCell(db, row, column, fallback, positive);
    if (v != earlier)
        throw Error(fmt::format("{}:{}: {} is {} but earlier rows of {} say {}; every channel row of it must "
                                "agree",
                                db.csvPath(), db.line(row), column, v, what, earlier));
}

std::string simpleQueryValue(const std::string& v) {
    if (v.find_first_of(",=\"") == std::string::npos && v.find(' ') == std::string::npos) return v;
    std::string out = "\"";
    for (char c : v) {
        if (c == '"') out += '"';
        out += c;
    }
    return out + "\"";
}

// Near and far of the camera when data.csv records them (TTK writes its
// camera field data as columns when asked to).
bool nearFarOf(const CinemaDatabase& db, std::size_t row, double& nearValue, double& farValue) {
    static const std::pair<const char*, const char*> names[] = {
        {"CamNear", "CamFar"}, {"CamNearFar_0", "CamNearFar_1"}, {"CamNearFar0", "CamNearFar1"}};
    for (const auto& [n, f] : names) {
        const auto cn = db.findColumn(n), cf = db.findColumn(f);
        if (!cn || !cf) continue;
        nearValue = db.number(row, *cn);
        farValue = db.number(row, *cf);
        if (std::isfinite(nearValue) && std::isfinite(farValue) && farValue > nearValue) return true;
    }
    return false;
}

}  // namespace

bool isComposableImageSet(const CinemaDatabase& db) {
    return db.findColumn("CISImage") && db.findColumn("CISLayer") && db.findColumn("CISChannel");
}

std::vector<CisImage> composableImages(const CinemaDatabase& db, const std::vector<std::size_t>& rowsIn) {
    if (!isComposableImageSet(db))
        throw Error(fmt::format("Cinema database '{}' is not a composable image set (it lacks the CISImage, "
                                "CISLayer and CISChannel columns)",
                                db.path()));
    std::vector<std::size_t> rows = rowsIn;
    if (rows.empty())
        for (std::size_t r = 0; r < db.rowCount(); ++r) rows.push_back(r);
    std::vector<CisImage> images;
    for (std::size_t r : rows) {
        const std::string& imageId = cellOf(db, r, "CISImage");
        const std::string& layerId = cellOf(db, r, "CISLayer");
        const std::string& channel = cellOf(db, r, "CISChannel");
        if (imageId.empty() || layerId.empty() || channel.empty())
            throw Error(fmt::format("{}:{}: CISImage, CISLayer and CISChannel must not be empty in a composable "
                                    "image set",
                                    db.csvPath(), db.line(r)));
        auto img = std::find_if(images.begin(), images.end(), [&](const CisImage& i) { return i.id == imageId; });
        if (img == images.end()) {
            CisImage i;
            i.id = imageId;
            i.width = integerCell(db, r, "CISImageWidth", 0, true);
            i.height = integerCell(db, r, "CISImageHeight", 0, true);
            i.origin = cis::parseOrigin(db, r);
            const auto originColumn = db.findColumn("CISOrigin");
            i.originStated = originColumn && !db.cell(r, *originColumn).empty();
            images.push_back(std::move(i));
            img = images.end() - 1;
        } else {
            sameAsEarlier(db, r, "CISImageWidth", img->width, 0, true, "image " + imageId);
            sameAsEarlier(db, r, "CISImageHeight", img->height, 0, true, "image " + imageId);
        }
        if (cis::parseOrigin(db, r) != img->origin && db.findColumn("CISOrigin")) {
            throw Error(fmt::format("{}:{}: CISOrigin is '{}' but earlier rows of image {} say {}; one image has "
                                    "one origin",
                                    db.csvPath(), db.line(r), cellOf(db, r, "CISOrigin"), imageId, img->origin));
        }
        auto layer = std::find_if(img->layers.begin(), img->layers.end(),
                                  [&](const CisLayer& l) { return l.id == layerId; });
        if (layer == img->layers.end()) {
            CisLayer l;
            l.id = layerId;
            l.width = integerCell(db, r, "CISLayerWidth", img->width, true);
            l.height = integerCell(db, r, "CISLayerHeight", img->height, true);
            l.offsetX = integerCell(db, r, "CISLayerOffsetX", 0, false);
            l.offsetY = integerCell(db, r, "CISLayerOffsetY", 0, false);
            l.query = "CISImage=" + simpleQueryValue(imageId) + ", CISLayer=" + simpleQueryValue(layerId);
            for (std::size_t c : db.parameterColumns()) {
                const std::string& name = db.columns()[c].name;
                if (isCisColumn(name)) continue;
                l.parameters += (l.parameters.empty() ? "" : ", ") + name + "=" + simpleQueryValue(db.cell(r, c));
            }
            img->layers.push_back(std::move(l));
            layer = img->layers.end() - 1;
        } else {
            const std::string what = "layer " + layerId + " of image " + imageId;
            sameAsEarlier(db, r, "CISLayerWidth", layer->width, img->width, true, what);
            sameAsEarlier(db, r, "CISLayerHeight", layer->height, img->height, true, what);
            sameAsEarlier(db, r, "CISLayerOffsetX", layer->offsetX, 0, false, what);
            sameAsEarlier(db, r, "CISLayerOffsetY", layer->offsetY, 0, false, what);
        }
        CisChannel ch;
        ch.row = r;
        ch.channel = channel;
        ch.variable = cellOf(db, r, "CISChannelVar");
        if (ch.variable.empty()) ch.variable = channel;
        ch.isDepth = channel == "CISDepth" || lower(ch.variable) == "depth";
        const std::string& cmap = cellOf(db, r, "CISChannelColormap");
        if (!cmap.empty()) {
            const fs::path p(cmap);
            ch.colormap = fs::absolute(p.is_absolute() ? p : fs::path(db.path()) / p).lexically_normal().string();
        }
        for (const auto& other : layer->channels)
            if (other.bufferName() == ch.bufferName())
                throw Error(fmt::format("{}:{}: layer {} of image {} has channel '{}' twice (also on line {})",
                                        db.csvPath(), db.line(r), layerId, imageId, ch.bufferName(),
                                        db.line(other.row)));
        layer->channels.push_back(std::move(ch));
    }
    for (auto& img : images) {
        // Images without explicit sizes take their largest layer's extent.
        for (const auto& l : img.layers) {
            if (img.width == 0) img.width = std::max(img.width, l.offsetX + l.width);
            if (img.height == 0) img.height = std::max(img.height, l.offsetY + l.height);
        }
    }
    return images;
}

std::shared_ptr<WritableBuffer> readComposableLayer(const CinemaDatabase& db, const CisImage& image,
                                                    const CisLayer& layer, Diagnostics* warnings) {
    std::vector<ChannelDesc> descs;
    for (const auto& ch : layer.channels) descs.push_back({ch.bufferName(), ChannelType::Float32});
    const int W = image.width, H = image.height;
    if (W <= 0 || H <= 0 || layer.width <= 0 || layer.height <= 0 || layer.offsetX + layer.width > W ||
        layer.offsetY + layer.height > H)
        throw Error(fmt::format("{}:{}: layer {} ({} x {} at {}, {}: CISLayerWidth/Height, CISLayerOffsetX/Y) does "
                                "not fit image {} ({} x {}: CISImageWidth/Height); expected offset + size within "
                                "the image",
                                db.csvPath(), layer.channels.empty() ? 0 : db.line(layer.channels.front().row),
                                layer.id, layer.width, layer.height, layer.offsetX, layer.offsetY, image.id, W, H));
    auto out = makeCpuBuffer(W, H, descs);
    auto& attrs = out->metadata().attributes;
    attrs["source"] = db.path();
    attrs["cis.image"] = image.id;
    attrs["cis.layer"] = layer.id;
    attrs["cis.origin"] = image.originStated ? image.origin : image.origin + " (assumed: no CISOrigin in data.csv)";
    for (const auto& ch : layer.channels) {
        // Layer-sized, stored [x][y]; the conversions below do not depend on the layout.
        std::vector<float> values = cis::readChannelValues(db, image, layer, ch, warnings);
        const float background = ch.isDepth ? kInf : kNaN;
        if (ch.isDepth) {
            // Which convention: NaN marks Ascent's raw distances; values
            // within [0,1] with a 1.0 background are TTK's normalised depth.
            bool anyNaN = false, within01 = true;
            for (float v : values) {
                anyNaN |= std::isnan(v);
                within01 &= std::isnan(v) || (v >= 0.f && v <= 1.f);
            }
            double nearValue = 0, farValue = 0;
            std::string convention;
            if (anyNaN) {
                for (float& v : values)
                    if (std::isnan(v)) v = kInf;
                convention = "raw distance (Ascent); NaN background -> +inf";
            } else if (within01) {
                const bool known = nearFarOf(db, ch.row, nearValue, farValue);
                for (float& v : values) {
                    if (v >= 1.f) v = kInf;
                    else if (known) v = float(nearValue + double(v) * (farValue - nearValue));
                }
                if (known) {
                    convention = fmt::format("TTK normalised depth; Z = near + d (far - near) with near {} far {}; "
                                             "1.0 background -> +inf",
                                             nearValue, farValue);
                } else {
                    // Recorded, not warned: compositing is right on normalised
                    // depth, and a depth-based pass reads it as normalised in
                    // image space and says so once per run (sdk depth_input.h).
                    convention = "TTK normalised depth kept in [0,1) (no camera near/far); 1.0 background -> +inf";
                }
            } else {
                convention = "raw distance kept as is";
            }
            attrs["depth.convention"] = convention;
        }
        float* dst = out->writeFloat(ch.bufferName());
        std::fill(dst, dst + std::size_t(W) * H, background);
        cis::placeLayer(values, image, layer, dst);
        if (!ch.colormap.empty()) attrs["colormap." + ch.bufferName()] = ch.colormap;
    }
    return out;
}

std::shared_ptr<WritableBuffer> readComposableRows(const CinemaDatabase& db, const std::vector<std::size_t>& rows,
                                                   Diagnostics* warnings) {
    if (rows.empty())
        throw Error(fmt::format("no row of Cinema database '{}' matches; nothing to read", db.path()));
    // The rows pick layers; all channels of that layer are read, not just the matched rows.
    const auto picked = composableImages(db, rows);
    const auto all = composableImages(db);
    std::vector<std::string> layers;
    for (const auto& img : picked)
        for (const auto& l : img.layers) layers.push_back(img.id + "/" + l.id + " (" + l.parameters + ")");
    if (layers.size() != 1) {
        std::string list;
        for (const auto& img : all)
            for (const auto& l : img.layers) list += fmt::format("\n  {}  [{}]", l.query, l.parameters);
        throw Error(fmt::format("Cinema database '{}' is a composable image set and the selection spans {} layers; "
                                "select one layer, e.g. with a parameter that picks one object or with one of:{}",
                                db.path(), layers.size(), list));
    }
    for (const auto& img : all)
        if (img.id == picked.front().id)
            for (const auto& l : img.layers)
                if (l.id == picked.front().layers.front().id) return readComposableLayer(db, img, l, warnings);
    throw Error("internal: selected layer vanished");  // unreachable: `all` contains every picked layer
}

}  // namespace darkroom
