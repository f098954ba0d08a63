#include "resize.h"

#include "image_checks.h"
#include "resample_taps.h"
#include "resize_kernel.h"

#include <darkroom/error.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace darkroom {

namespace {

// Rounded, at least 1, and capped so the size check below sees it instead of an int overflow.
int derived(double size) { return int(std::clamp(std::round(size), 1.0, 1e9)); }

// The output size: width and height as asked, one of them with the other
// derived from the aspect ratio, or the input scaled.
std::pair<int, int> outputSize(int w, int h, std::int64_t askW, std::int64_t askH, double scale) {
    if (askW > 0 && askH > 0) return {int(askW), int(askH)};
    if (askW > 0) return {int(askW), derived(double(askW) * h / w)};
    if (askH > 0) return {derived(double(askH) * w / h), int(askH)};
    return {derived(w * scale), derived(h * scale)};
}

// One channel to resample: where it comes from and goes to.
struct ChannelJob {
    const ChannelDesc* desc;
    const float* source;
    const float* weightBy;
    bool fromSourcePixel;  // Z and uint32 channels: copied from one source pixel
    void* out;
};

std::vector<ChannelJob> channelJobs(const Buffer& in, WritableBuffer& out) {
    const float* alpha = in.hostFloat("A");
    std::vector<ChannelJob> planes;
    for (const ChannelDesc& c : in.channels()) {
        ChannelJob p{&c, nullptr, nullptr, c.type == ChannelType::UInt32 || c.name == "Z", nullptr};
        if (c.type == ChannelType::UInt32) {
            p.source = reinterpret_cast<const float*>(in.hostUInt(c.name));
            p.out = out.writeUInt(c.name);
        } else {
            p.source = in.hostFloat(c.name);
            p.out = out.writeFloat(c.name);
            // Straight-alpha colour is averaged weighted by alpha (what a
            // premultiplied average divided by the mean alpha gives), so edges
            // against transparent background do not darken.
            if (alpha && (c.name == "R" || c.name == "G" || c.name == "B")) p.weightBy = alpha;
        }
        planes.push_back(p);
    }
    return planes;
}

}  // namespace

namespace utils {

std::size_t nearestDepthSource(const ResizeRow& row, const float* depth, int x, std::size_t fallback) {
    std::size_t best = fallback;
    float bestZ = std::numeric_limits<float>::infinity();
    for (const Tap* sy = row.yBegin; sy != row.yEnd; ++sy)
        for (const Tap* sx = row.tx->begin(x); sx != row.tx->end(x); ++sx) {
            const std::size_t i = std::size_t(sy->index) * std::size_t(row.sourceWidth) + std::size_t(sx->index);
            if (depth[i] < bestZ && std::isfinite(depth[i])) {
                bestZ = depth[i];
                best = i;
            }
        }
    return best;
}

float resampleAt(const ResizeRow& row, const float* s, const float* weightBy, int x) {
    double sumA = 0, weightA = 0, sum = 0, weight = 0;
    for (const Tap* sy = row.yBegin; sy != row.yEnd; ++sy)
        for (const Tap* sx = row.tx->begin(x); sx != row.tx->end(x); ++sx) {
            const std::size_t i = std::size_t(sy->index) * std::size_t(row.sourceWidth) + std::size_t(sx->index);
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
    const double value = weightA > 0 ? sumA / weightA : weight > 0 ? sum / weight : std::numeric_limits<double>::quiet_NaN();
    return float(value);
}

PaddedTaps padTaps(const AxisTaps& a, int outputs) {
    PaddedTaps p;
    for (int o = 0; o < outputs; ++o) p.count = std::max(p.count, int(a.end(o) - a.begin(o)));
    p.index.assign(std::size_t(p.count) * std::size_t(outputs), 0);
    p.weight.assign(p.index.size(), 0.0);
    for (int o = 0; o < outputs; ++o) {
        const Tap* t = a.begin(o);
        const int n = int(a.end(o) - t);
        for (int k = 0; k < p.count; ++k) {
            const std::size_t at = std::size_t(k) * std::size_t(outputs) + std::size_t(o);
            // Padding repeats the first tap with weight 0.
            p.index[at] = k < n ? t[k].index : (n > 0 ? t[0].index : 0);
            p.weight[at] = k < n ? t[k].weight : 0.0;
        }
    }
    return p;
}

}  // namespace utils

void Resize::execute(Context& ctx) {
    const BufferPtr in = ctx.get(image_);
    const int w = in->width(), h = in->height();
    if (w <= 0 || h <= 0) throw Error("the input image is empty (" + utils::sizeText(*in) + ")");
    const auto [outW, outH] = outputSize(w, h, ctx.get(width_), ctx.get(height_), ctx.get(scale_));
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

    // Every channel is resampled into every output pixel.
    auto out = ctx.allocate(outW, outH, in->channels(), Fill::None);
    out->metadata() = in->metadata();
    if (out->metadata().camera) {
        out->metadata().camera->width = outW;
        out->metadata().camera->height = outH;
    }

    // Row by row: the source pixel that gives depth and ids, then every
    // channel of the row (a vector of output pixels at a time where the
    // source is small enough for 32-bit indices).
    const bool nearestDepth = depth && filter == utils::ResampleFilter::Box;
    const bool simd = std::int64_t(w) * h < (std::int64_t(1) << 31);
    const utils::PaddedTaps px = simd ? utils::padTaps(tx, outW) : utils::PaddedTaps{};
    const std::vector<ChannelJob> planes = channelJobs(*in, *out);
    ctx.parallelFor(0, outH, 8, [&](int y0, int y1) {
        std::vector<std::int32_t> fallback(static_cast<std::size_t>(outW)), source(static_cast<std::size_t>(outW));
        for (int y = y0; y < y1; ++y) {
            const utils::ResizeRow row{&tx, ty.begin(y), ty.end(y), w, outW};
            const std::size_t first = std::size_t(y) * std::size_t(outW);
            // The one source pixel that gives depth and ids. A box footprint takes its
            // nearest surface (any geometry in the footprint makes the pixel geometry,
            // like alpha coverage does); ties keep the first in scan order.
            std::vector<std::size_t> wide(simd ? 0 : std::size_t(outW));
            for (int x = 0; x < outW; ++x) {
                const std::size_t nearest = std::size_t(ty.nearest[std::size_t(y)]) * std::size_t(w) +
                                            std::size_t(tx.nearest[std::size_t(x)]);
                if (simd)
                    fallback[std::size_t(x)] = std::int32_t(nearest);
                else
                    wide[std::size_t(x)] = nearestDepth ? utils::nearestDepthSource(row, depth, x, nearest) : nearest;
            }
            if (simd) {
                if (nearestDepth) {
                    int x = utils::nearestDepthRow(row, px, depth, fallback.data(), source.data());
                    for (; x < outW; ++x)
                        source[std::size_t(x)] =
                            std::int32_t(utils::nearestDepthSource(row, depth, x, std::size_t(fallback[std::size_t(x)])));
                } else {
                    source = fallback;
                }
            }
            for (const ChannelJob& p : planes) {
                if (p.fromSourcePixel) {
                    const auto* s = reinterpret_cast<const std::uint32_t*>(p.source);
                    auto* d = static_cast<std::uint32_t*>(p.out) + first;
                    int x = simd ? utils::gatherRow(s, source.data(), outW, d) : 0;
                    for (; x < outW; ++x) d[x] = s[simd ? std::size_t(source[std::size_t(x)]) : wide[std::size_t(x)]];
                    continue;
                }
                float* d = static_cast<float*>(p.out) + first;
                int x = simd ? utils::resampleRow(row, px, p.source, p.weightBy, d) : 0;
                for (; x < outW; ++x) d[x] = utils::resampleAt(row, p.source, p.weightBy, x);
            }
        }
    });
    if (ctx.cancelled()) throw Cancelled();
    ctx.progress(1.0);
    ctx.set(result_, out);
}

}  // namespace darkroom
