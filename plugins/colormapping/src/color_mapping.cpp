#include "color_mapping.h"

#include "scalar_range.h"

#include <darkroom/colormap.h>
#include <darkroom/error.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace darkroom {

namespace {

// Entries in the lookup table: linear interpolation between them stays far
// below 8-bit resolution for every preset, and both ends are exact samples.
constexpr int kTableSize = 4096;

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

void ColorMapping::execute(Context& ctx) {
    const BufferPtr in = ctx.get(image_);
    const std::string channel = chooseChannel(*in, ctx.get(channel_));
    ScalarChannel scalar{in->hostFloat(channel), in->hostUInt(channel)};
    const float* depth = in->hostFloat("Z");
    const int w = in->width(), h = in->height();

    const ColorMapData map = loadColorMap(ctx.get(colormap_));
    const std::vector<Color> table = map.table(kTableSize);
    const Color nan = ctx.get(useMapNanColor_) && map.hasNanColor ? map.nanColor : ctx.get(nanColor_);
    const float alpha = float(ctx.get(opacity_));

    const bool logScale = ctx.get(scale_) == Scale::Log;
    double low = std::numeric_limits<double>::quiet_NaN(), high = low;
    if (ctx.get(range_) == Range::Manual) {
        low = ctx.get(minimum_);
        high = ctx.get(maximum_);
        if (!std::isfinite(low) || !std::isfinite(high))
            throw Error("a manual range needs finite minimum and maximum");
        if (logScale && !(low > 0 && high > 0))
            throw Error("a log scale needs a positive manual range; got minimum " + std::to_string(low) +
                        " and maximum " + std::to_string(high));
    } else {
        const ScalarRange r = finiteRange(ctx, scalar, depth, w, h, logScale);
        if (r.found) {
            low = r.low;
            high = r.high;
        }
    }

    // Colour is written for every pixel; depth is the input's plane, shared.
    auto out = ctx.allocate(w, h, {"R", "G", "B", "A"}, Fill::None);
    if (depth) out->setPlane({"Z"}, in->plane("Z"));
    out->metadata() = in->metadata();
    float* R = out->writeFloat("R");
    float* G = out->writeFloat("G");
    float* B = out->writeFloat("B");
    float* A = out->writeFloat("A");
    const bool haveRange = !std::isnan(low);
    ctx.parallelFor(0, h, 8, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < w; ++x) {
                const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
                // Background (depth +inf) is transparent black.
                Color c{0.0f, 0.0f, 0.0f, 0.0f};
                const bool background = depth && std::isinf(depth[i]) && depth[i] > 0;
                const double v = scalar[i];
                if (background) {
                    // keep transparent
                } else if (std::isnan(v) || !haveRange) {
                    c = nan;
                } else {
                    const double f = (logScale ? logPosition(v, low, high) : position(v, low, high)) * (kTableSize - 1);
                    const int k = std::min(int(f), kTableSize - 2);
                    const float t = float(f - k), s = 1.0f - t;
                    // This form returns either entry exactly at t = 0 and t = 1.
                    const Color& a = table[std::size_t(k)];
                    const Color& b = table[std::size_t(k) + 1];
                    c = {s * a.r + t * b.r, s * a.g + t * b.g, s * a.b + t * b.b, alpha};
                }
                R[i] = c.r;
                G[i] = c.g;
                B[i] = c.b;
                A[i] = c.a;
            }
    });
    ctx.progress(1.0);
    ctx.set(result_, out);
    ctx.set(usedMinimum_, low);
    ctx.set(usedMaximum_, high);
    ctx.set(usedScale_, Value(logScale ? "log" : "linear"));
    ctx.set(usedColormap_, Value(ctx.get(colormap_)));
}

}  // namespace darkroom
