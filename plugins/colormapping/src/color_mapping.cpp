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

std::string chooseChannel(const Buffer& image, const std::string& asked, const std::string& node) {
    if (!asked.empty()) {
        if (!image.hasChannel(asked)) {
            std::string have;
            for (const auto& c : image.channels()) have += (have.empty() ? "" : ", ") + c.name;
            throw Error(node + ": the image has no channel '" + asked + "'; it has " +
                        (have.empty() ? std::string("no channels") : have));
        }
        return asked;
    }
    for (const auto& c : image.channels())
        if (c.type == ChannelType::Float32 && c.name != "Z" && c.name != "A") return c.name;
    std::string have;
    for (const auto& c : image.channels()) have += (have.empty() ? "" : ", ") + c.name;
    throw Error(node + ": no scalar channel to map (the image has " +
                (have.empty() ? std::string("no channels") : have) + "); set 'channel'");
}

// Position in the map of value v for the range [low, high]. A reversed range
// (high < low) flips the map; an empty one puts its value in the middle.
double position(double v, double low, double high) {
    if (high == low) return v < low ? 0.0 : (v > low ? 1.0 : 0.5);
    return std::clamp((v - low) / (high - low), 0.0, 1.0);
}

}  // namespace

PortList ColorMapping::ports() const {
    PortList p;
    p.imageIn("image", "Image holding the scalar channel (and optionally depth Z)");
    p.stringIn("channel", "",
               "Scalar channel to map (float32 or uint32); empty = the first float32 channel "
               "other than Z and A");
    p.colorMapIn("colormap", "viridis",
                 "Preset name or a ParaView colour-map JSON file (relative to the pipeline file)");
    p.enumIn("range", {"automatic", "manual"}, "automatic",
             "automatic: the finite minimum and maximum of the channel over non-background pixels; "
             "manual: minimum and maximum below");
    const double big = 1e30;  // no practical limit on data values
    p.floatIn("minimum", 0.0, -big, big, "Value mapped to the start of the map (manual range)");
    p.floatIn("maximum", 1.0, -big, big,
              "Value mapped to the end of the map (manual range); below minimum flips the map");
    p.colorIn("nanColor", Color{1.0f, 1.0f, 0.0f, 1.0f}, "Linear colour for NaN values");
    p.boolIn("useMapNanColor", false,
             "Use the colour map's own NaN colour when it defines one (ParaView JSON NanColor, "
             "cool-to-warm, blackbody) instead of nanColor");
    p.floatIn("opacity", 1.0, 0.0, 1.0, "Alpha of mapped pixels (NaN pixels take nanColor's alpha)");
    p.imageOut("image",
               "Linear R, G, B, A (straight alpha) plus the input's Z; pixels whose Z is +inf are "
               "transparent black",
               {"R", "G", "B", "A"});
    p.valueOut("usedMinimum", PortType::Float, "Value mapped to the start of the map (NaN if none)");
    p.valueOut("usedMaximum", PortType::Float, "Value mapped to the end of the map (NaN if none)");
    return p;
}

void ColorMapping::execute(Context& ctx) {
    const BufferPtr in = ctx.requireImage("image");
    const std::string node = "ColorMapping '" + ctx.nodeName() + "'";
    const std::string channel = chooseChannel(*in, ctx.getString("channel"), node);
    ScalarChannel scalar{in->hostFloat(channel), in->hostUInt(channel)};
    const float* depth = in->hostFloat("Z");
    const int w = in->width(), h = in->height();

    const std::string& spec = ctx.getString("colormap");
    const ColorMapData map = loadColorMap(isColorMapPreset(spec) || spec.empty() ? spec : ctx.resolveInputPath(spec));
    const std::vector<Color> table = map.table(kTableSize);
    const Color nan = ctx.getBool("useMapNanColor") && map.hasNanColor ? map.nanColor : ctx.getColor("nanColor");
    const float alpha = float(ctx.getFloat("opacity"));

    double low = std::numeric_limits<double>::quiet_NaN(), high = low;
    if (ctx.getString("range") == "manual") {
        low = ctx.getFloat("minimum");
        high = ctx.getFloat("maximum");
        if (!std::isfinite(low) || !std::isfinite(high))
            throw Error(node + ": a manual range needs finite minimum and maximum");
    } else {
        const ScalarRange r = finiteRange(ctx, scalar, depth, w, h);
        if (r.found) {
            low = r.low;
            high = r.high;
        }
    }
    if (ctx.cancelled()) return;

    std::vector<ChannelDesc> channels{{"R"}, {"G"}, {"B"}, {"A"}};
    if (depth) channels.push_back({"Z"});
    auto out = ctx.allocate(w, h, channels);
    out->metadata() = in->metadata();
    float* R = out->hostFloat("R");
    float* G = out->hostFloat("G");
    float* B = out->hostFloat("B");
    float* A = out->hostFloat("A");
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
                    const double f = position(v, low, high) * (kTableSize - 1);
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
    if (ctx.cancelled()) return;
    if (depth) std::copy(depth, depth + in->pixelCount(), out->hostFloat("Z"));
    ctx.progress(1.0);
    ctx.setOutput("image", BufferPtr(std::move(out)));
    ctx.setOutput("usedMinimum", Value(low));
    ctx.setOutput("usedMaximum", Value(high));
}

}  // namespace darkroom
