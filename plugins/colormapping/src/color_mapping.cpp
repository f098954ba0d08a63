#include "color_mapping.h"

#include "database_range.h"
#include "map_kernel.h"
#include "map_layers.h"
#include "object_opacity.h"
#include "scalar_range.h"

#include <darkroom/colormap.h>
#include <darkroom/error.h>
#include <darkroom/layers.h>

#include <algorithm>
#include <utility>
#include <vector>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <mutex>

namespace darkroom {

namespace {

using colormapping::kTableSize;

std::string chooseChannel(const Buffer& image, const std::string& asked) {
    if (!asked.empty()) {
        if (!image.hasChannel(asked)) {
            std::string have;
            for (const auto& c : image.channels()) have += (have.empty() ? "" : ", ") + c.name;
            throw Error("the image has no channel '" + asked + "'; it has " +
                        (have.empty() ? std::string("no channels") : have));
        }
        return asked;
    }
    for (const auto& c : image.channels())
        if (c.type == ChannelType::Float32 && c.name != "Z" && c.name != "A") return c.name;
    std::string have;
    for (const auto& c : image.channels()) have += (have.empty() ? "" : ", ") + c.name;
    throw Error("no scalar channel to map (the image has " +
                (have.empty() ? std::string("no channels") : have) + "); set 'channel'");
}

// A colour map with its lookup tables.
struct Lookup {
    ColorMapData map;
    std::vector<Color> table;
    std::vector<std::uint64_t> pairs;
};

// Building the table costs a colour-space conversion per entry (~0.3 ms, a
// tenth of mapping a megapixel), so the tables of presets, which never
// change, are kept; a file is read every time (it may have been edited).
std::shared_ptr<const Lookup> lookupFor(const std::string& spec) {
    auto make = [&] {
        auto l = std::make_shared<Lookup>();
        l->map = loadColorMap(spec);
        l->table = l->map.table(kTableSize);
        l->pairs = colormapping::tablePairs(l->table);
        return l;
    };
    if (!isColorMapPreset(spec)) return make();
    static std::mutex mutex;
    static std::map<std::string, std::shared_ptr<const Lookup>> presets;
    std::lock_guard<std::mutex> lock(mutex);
    auto& cached = presets[spec];
    if (!cached) cached = make();
    return cached;
}

}  // namespace

namespace colormapping {

namespace {

// Position in the map of value v for the range [low, high]. A reversed range
// (high < low) flips the map; an empty one puts its value in the middle.
double position(double v, double low, double high) {
    if (high == low) return v < low ? 0.0 : (v > low ? 1.0 : 0.5);
    return std::clamp((v - low) / (high - low), 0.0, 1.0);
}

// The same on a log scale (low, high > 0): values <= 0 lie below any positive
// range, so they take the start of the map (the end, for a reversed range).
double logPosition(double v, double low, double high) {
    if (!(v > 0)) return high < low ? 1.0 : 0.0;
    return position(std::log10(v), std::log10(low), std::log10(high));
}

}  // namespace

std::vector<std::uint64_t> tablePairs(const std::vector<Color>& table) {
    const std::size_t n = kTableSize - 1;
    std::vector<std::uint64_t> pairs(3 * n);
    for (int c = 0; c < 3; ++c)
        for (std::size_t k = 0; k < n; ++k) {
            std::uint32_t a, b;
            std::memcpy(&a, &(&table[k].r)[c], 4);
            std::memcpy(&b, &(&table[k + 1].r)[c], 4);
            pairs[std::size_t(c) * n + k] = std::uint64_t(a) | std::uint64_t(b) << 32;
        }
    return pairs;
}

Color mapValue(const MapJob& job, std::size_t i, double v) {
    // Background (depth +inf) is transparent black.
    if (job.depth && std::isinf(job.depth[i]) && job.depth[i] > 0) return {0.0f, 0.0f, 0.0f, 0.0f};
    if (std::isnan(v) || !job.haveRange) return job.nan;
    const double f = position(v, job.low, job.high) * (kTableSize - 1);
    const int k = std::min(int(f), kTableSize - 2);
    const float t = float(f - k), s = 1.0f - t;
    // This form returns either entry exactly at t = 0 and t = 1.
    const Color& a = job.table[std::size_t(k)];
    const Color& b = job.table[std::size_t(k) + 1];
    return {s * a.r + t * b.r, s * a.g + t * b.g, s * a.b + t * b.b, job.alpha};
}

}  // namespace colormapping

namespace {

// The clip-th and (100 - clip)-th percentiles of the finite values over
// non-background pixels (positive ones on a log scale).
// Over every layer's values that count.
ScalarRange percentileRange(const std::vector<colormapping::LayerValues>& layers, std::size_t n, double clip,
                            bool positiveOnly) {
    std::vector<double> v;
    v.reserve(n);
    for (const colormapping::LayerValues& layer : layers)
        for (std::size_t i = 0; i < n; ++i) {
            const float* depth = layer.depth;
            if (depth && std::isinf(depth[i]) && depth[i] > 0) continue;
            const double x = layer.scalar[i];
            if (std::isfinite(x) && (!positiveOnly || x > 0)) v.push_back(x);
        }
    ScalarRange r;
    if (v.empty()) return r;
    const auto at = [&v](double q) {
        const auto k = std::size_t(std::llround(q * double(v.size() - 1)));
        std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(k), v.end());
        return v[k];
    };
    r.low = at(clip / 100.0);
    r.high = at(1.0 - clip / 100.0);
    r.found = true;
    return r;
}

// A range narrower than the float resolution of its values is rounding, not
// data (a near-constant field would spread its last bits over the whole map):
// it becomes one value, mapped to the middle of the map.
bool collapseRounding(double& low, double& high) {
    const double scale = std::max(std::fabs(low), std::fabs(high));
    if (high - low > 4.0 * double(std::numeric_limits<float>::epsilon()) * scale || high == low) return false;
    low = high = (low + high) / 2;
    return true;
}

}  // namespace

ColorMapping::ChosenRange ColorMapping::chooseRange(Context& ctx, const Buffer& in, const std::string& channel,
                                                    const std::vector<colormapping::LayerValues>& values) const {
    const bool logScale = ctx.get(scale_) == Scale::Log;
    const Range mode = ctx.get(range_);
    if (mode == Range::Manual) {
        const double low = ctx.get(minimum_), high = ctx.get(maximum_);
        if (!std::isfinite(low) || !std::isfinite(high)) throw Error("a manual range needs finite minimum and maximum");
        if (logScale && !(low > 0 && high > 0))
            throw Error("a log scale needs a positive manual range; got minimum " + std::to_string(low) +
                        " and maximum " + std::to_string(high));
        return {low, high, false};
    }
    const double clip = ctx.get(clip_);
    const bool symmetric = ctx.get(symmetric_);
    if (symmetric && logScale) throw Error("a log scale cannot be symmetric about zero; turn off 'symmetric'");
    ScalarRange r;
    if (mode == Range::Database) {
        const auto& attributes = in.metadata().attributes;
        const auto source = attributes.find("source"), selection = attributes.find("run.selection");
        const DatabaseRange d = databaseRange(source == attributes.end() ? "" : source->second,
                                              selection == attributes.end() ? "" : selection->second, channel,
                                              logScale, clip, [&ctx](double f) { ctx.progress(0.5 * f); });
        r.found = d.found, r.low = d.low, r.high = d.high;
        // A database written again (a new capture) changes the range.
        ctx.readsFile((std::filesystem::path(d.database) / "data.csv").string());
    } else if (clip > 0) {
        r = percentileRange(values, in.pixelCount(), clip, logScale);
    } else {
        // min and max merge in any order: the layers' ranges give the whole one.
        for (const colormapping::LayerValues& layer : values) {
            const ScalarRange l = finiteRange(ctx, layer.scalar, layer.depth, in.width(), in.height(), logScale);
            if (!l.found) continue;
            r.low = r.found ? std::min(r.low, l.low) : l.low;
            r.high = r.found ? std::max(r.high, l.high) : l.high;
            r.found = true;
        }
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    if (!r.found) return {nan, nan, false};
    if (symmetric) {
        const double m = std::max(std::fabs(r.low), std::fabs(r.high));
        r.low = -m, r.high = m;
    }
    const bool constant = collapseRounding(r.low, r.high);
    return {r.low, r.high, constant};
}

std::string ColorMapping::chooseColorMap(Context& ctx, const Buffer& in, const std::string& channel) const {
    const std::string asked = ctx.get(colormap_);
    if (!asked.empty()) return asked;
    // A composable image set names its channel's map in data.csv; CinemaReader
    // passes it on as metadata (data/cinema/composable.h).
    const auto& attributes = in.metadata().attributes;
    const auto stored = attributes.find("colormap." + channel);
    if (stored == attributes.end() || stored->second.empty()) return "viridis";
    ctx.readsFile(stored->second);  // an edited map maps again
    return stored->second;
}

namespace colormapping {

void mapPixels(Context& ctx, const MapJob& job, const ScalarChannel& scalar, int w, int h, bool logScale) {
    const float* depth = job.depth;
    ctx.parallelFor(0, h, 8, [&](int y0, int y1) {
        if (logScale) {
            // Log scale: per value (the SIMD span below is linear).
            for (int y = y0; y < y1; ++y)
                for (int x = 0; x < w; ++x) {
                    const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
                    // Background (depth +inf) is transparent black.
                    Color c{0.0f, 0.0f, 0.0f, 0.0f};
                    const bool background = depth && std::isinf(depth[i]) && depth[i] > 0;
                    const double v = scalar[i];
                    if (background) {
                        // keep transparent
                    } else if (std::isnan(v) || !job.haveRange) {
                        c = job.nan;
                    } else {
                        const double f = logPosition(v, job.low, job.high) * (kTableSize - 1);
                        const int k = std::min(int(f), kTableSize - 2);
                        const float t = float(f - k), s = 1.0f - t;
                        // This form returns either entry exactly at t = 0 and t = 1.
                        const Color& a = job.table[std::size_t(k)];
                        const Color& b = job.table[std::size_t(k) + 1];
                        c = {s * a.r + t * b.r, s * a.g + t * b.g, s * a.b + t * b.b, job.alpha};
                    }
                    job.out[0][i] = c.r;
                    job.out[1][i] = c.g;
                    job.out[2][i] = c.b;
                    job.out[3][i] = c.a;
                }
            return;
        }
        const std::size_t begin = std::size_t(y0) * std::size_t(w), end = std::size_t(y1) * std::size_t(w);
        std::size_t i = scalar.f ? mapSpan(job, scalar.f, begin, end) : begin;
        for (; i < end; ++i) {
            const Color c = mapValue(job, i, scalar[i]);
            job.out[0][i] = c.r;
            job.out[1][i] = c.g;
            job.out[2][i] = c.b;
            job.out[3][i] = c.a;
        }
    });
}

}  // namespace colormapping

void ColorMapping::execute(Context& ctx) {
    const BufferPtr in = ctx.get(image_);
    const std::string channel = chooseChannel(*in, ctx.get(channel_));
    ScalarChannel scalar{in->hostFloat(channel), in->hostUInt(channel)};
    const float* depth = in->hostFloat("Z");
    const int w = in->width(), h = in->height();
    const int layerCount = depth ? layers::count(*in) : 1;
    const colormapping::ObjectOpacity objects = colormapping::ObjectOpacity::parse(ctx.get(objectOpacity_));

    const std::string colormap = chooseColorMap(ctx, *in, channel);
    const std::shared_ptr<const Lookup> lookup = lookupFor(colormap);
    const ColorMapData& map = lookup->map;
    // Without depth, NaN is how ParaView's float images (and TTK's) mark the
    // background: transparent, as background with depth is.
    const Color nan = !depth ? Color{0.0f, 0.0f, 0.0f, 0.0f}
                             : (ctx.get(useMapNanColor_) && map.hasNanColor ? map.nanColor : ctx.get(nanColor_));
    const float alpha = float(ctx.get(opacity_));

    // The automatic range spans the values that can be seen: of one layer,
    // all of it; of several, each layer where nothing opaque is in front.
    std::vector<colormapping::LayerValues> values{{scalar, depth}};
    std::vector<std::vector<float>> visible;
    if (layerCount > 1) {
        visible = colormapping::visibleDepths(*in, layerCount, alpha, objects);
        values.clear();
        for (int k = 0; k < layerCount; ++k) {
            const std::string name = layers::channel(channel, k);
            values.push_back({{in->hostFloat(name), in->hostUInt(name)}, visible[std::size_t(k)].data()});
            if (!values.back().scalar.f && !values.back().scalar.u)
                throw Error("layer " + std::to_string(k) + " of the image has no channel '" + name +
                            "'; every layer needs the mapped channel");
        }
    }
    const bool logScale = ctx.get(scale_) == Scale::Log;
    const ChosenRange range = chooseRange(ctx, *in, channel, values);
    visible.clear();
    const double low = range.low, high = range.high;
    // A constant field maps to the middle of the map: mapped over a range
    // wide beside its last bits, every value lands there.
    const double spread = range.constant ? std::max(1.0, std::fabs(low)) : 0.0;

    colormapping::MapJob job;
    job.table = lookup->table.data();
    for (int c = 0; c < 3; ++c) job.pairs[c] = lookup->pairs.data() + std::size_t(c) * (kTableSize - 1);
    job.nan = nan;
    job.alpha = alpha;
    job.haveRange = !std::isnan(low);
    job.low = logScale ? low / (1 + spread) : low - spread;
    job.high = logScale ? high * (1 + spread) : high + spread;
    if (layerCount > 1) {
        ctx.set(result_, colormapping::mapLayers(ctx, in, channel, job, logScale, objects,
                                                 ctx.get(layers_) == Layers::Keep));
    } else {
        // Colour is written for every pixel; depth is the input's plane, shared.
        auto out = ctx.allocate(w, h, {"R", "G", "B", "A"}, Fill::None);
        if (depth) out->setPlane({"Z"}, in->plane("Z"));
        out->metadata() = in->metadata();
        job.depth = depth;
        for (int c = 0; c < 4; ++c) job.out[c] = out->writeFloat(std::string(1, "RGBA"[c]));
        colormapping::mapPixels(ctx, job, scalar, w, h, logScale);
        if (!objects.empty())
            colormapping::applyObjectOpacity(ctx, objects, colormapping::objectIds(*in, 0), depth, job.out[3],
                                             in->pixelCount());
        ctx.set(result_, out);
    }
    ctx.progress(1.0);
    ctx.set(usedMinimum_, low);
    ctx.set(usedMaximum_, high);
    ctx.set(usedScale_, Value(logScale ? "log" : "linear"));
    ctx.set(usedColormap_, Value(colormap));
}

}  // namespace darkroom
