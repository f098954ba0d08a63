#include "resize.h"

#include "image_checks.h"
#include "resample_taps.h"

#include <darkroom/error.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace darkroom {

namespace {

// Rounded, at least 1, and capped so the size check below sees it instead of an int overflow.
int derived(double size) { return int(std::clamp(std::round(size), 1.0, 1e9)); }

}  // namespace

void Resize::execute(Context& ctx) {
    const BufferPtr in = ctx.get(image_);
    const int w = in->width(), h = in->height();
    if (w <= 0 || h <= 0) throw Error("the input image is empty (" + utils::sizeText(*in) + ")");
    const std::int64_t askW = ctx.get(width_), askH = ctx.get(height_);
    const double scale = ctx.get(scale_);
    int outW, outH;
    if (askW > 0 && askH > 0) {
        outW = int(askW);
        outH = int(askH);
    } else if (askW > 0) {
        outW = int(askW);
        outH = derived(double(askW) * h / w);
    } else if (askH > 0) {
        outH = int(askH);
        outW = derived(double(askH) * w / h);
    } else {
        outW = derived(w * scale);
        outH = derived(h * scale);
    }
    if (outW > kMaxSide || outH > kMaxSide || std::int64_t(outW) * outH > kMaxPixels)
        throw Error("output " + std::to_string(outW) + "x" + std::to_string(outH) + " exceeds " +
                    std::to_string(kMaxSide) + " pixels per side or " + std::to_string(kMaxPixels) +
                    " pixels in all");
    if (outW == w && outH == h) {
        ctx.set(result_, in);  // nothing to resample
        return;
    }
    if (std::abs(double(outW) / outH - double(w) / h) > 0.01 * double(w) / h)
        ctx.warn(utils::sizeText(*in) + " to " + std::to_string(outW) + "x" + std::to_string(outH) +
                 " changes the aspect ratio; the camera's horizontal field of view no longer matches the pixels");

    const utils::ResampleFilter filter = ctx.get(filter_);
    const utils::AxisTaps tx = utils::axisTaps(w, outW, filter), ty = utils::axisTaps(h, outH, filter);
    const float* depth = in->hostFloat("Z");
    const float* alpha = in->hostFloat("A");

    // Every channel is resampled into every output pixel.
    auto out = ctx.allocate(outW, outH, in->channels(), Fill::None);
    out->metadata() = in->metadata();
    if (out->metadata().camera) {
        out->metadata().camera->width = outW;
        out->metadata().camera->height = outH;
    }

    // The one source pixel that gives depth and ids. A box footprint takes its
    // nearest surface (any geometry in the footprint makes the pixel geometry,
    // like alpha coverage does); ties keep the first in scan order.
    const std::size_t outN = std::size_t(outW) * std::size_t(outH);
    std::vector<std::size_t> source(outN);
    const bool nearestDepth = depth && filter == utils::ResampleFilter::Box;
    ctx.parallelFor(0, outH, 8, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < outW; ++x) {
                std::size_t best = std::size_t(ty.nearest[std::size_t(y)]) * std::size_t(w) +
                                   std::size_t(tx.nearest[std::size_t(x)]);
                if (nearestDepth) {
                    float bestZ = std::numeric_limits<float>::infinity();
                    for (const auto* sy = ty.begin(y); sy != ty.end(y); ++sy)
                        for (const auto* sx = tx.begin(x); sx != tx.end(x); ++sx) {
                            const std::size_t i = std::size_t(sy->index) * std::size_t(w) + std::size_t(sx->index);
                            if (depth[i] < bestZ && std::isfinite(depth[i])) {
                                bestZ = depth[i];
                                best = i;
                            }
                        }
                }
                source[std::size_t(y) * std::size_t(outW) + std::size_t(x)] = best;
            }
    });

    for (const ChannelDesc& c : in->channels()) {
        if (ctx.cancelled()) throw Cancelled();
        if (c.type == ChannelType::UInt32 || c.name == "Z") {
            if (c.type == ChannelType::UInt32) {
                const std::uint32_t* s = in->hostUInt(c.name);
                std::uint32_t* d = out->writeUInt(c.name);
                for (std::size_t i = 0; i < outN; ++i) d[i] = s[source[i]];
            } else {
                const float* s = in->hostFloat(c.name);
                float* d = out->writeFloat(c.name);
                for (std::size_t i = 0; i < outN; ++i) d[i] = s[source[i]];
            }
            continue;
        }
        const float* s = in->hostFloat(c.name);
        float* d = out->writeFloat(c.name);
        // Straight-alpha colour is averaged weighted by alpha (what a
        // premultiplied average divided by the mean alpha gives), so edges
        // against transparent background do not darken.
        const float* weightBy = (alpha && (c.name == "R" || c.name == "G" || c.name == "B")) ? alpha : nullptr;
        ctx.parallelFor(0, outH, 8, [&](int y0, int y1) {
            for (int y = y0; y < y1; ++y)
                for (int x = 0; x < outW; ++x) {
                    double sumA = 0, weightA = 0, sum = 0, weight = 0;
                    for (const auto* sy = ty.begin(y); sy != ty.end(y); ++sy)
                        for (const auto* sx = tx.begin(x); sx != tx.end(x); ++sx) {
                            const std::size_t i = std::size_t(sy->index) * std::size_t(w) + std::size_t(sx->index);
                            const float v = s[i];
                            if (!std::isfinite(v)) continue;  // NaN = no data, never averaged in
                            const double wt = sy->weight * sx->weight;
                            sum += wt * v;
                            weight += wt;
                            if (weightBy && weightBy[i] > 0.0f && std::isfinite(weightBy[i])) {
                                sumA += wt * weightBy[i] * v;
                                weightA += wt * weightBy[i];
                            }
                        }
                    const double value = weightA > 0 ? sumA / weightA
                                         : weight > 0 ? sum / weight
                                                      : std::numeric_limits<double>::quiet_NaN();
                    d[std::size_t(y) * std::size_t(outW) + std::size_t(x)] = float(value);
                }
        });
    }
    ctx.progress(1.0);
    ctx.set(result_, out);
}

}  // namespace darkroom
