#include "fxaa.h"

#include "fxaa_kernel.h"
#include "fxaa_presets.h"
#include "fxaa_simd.h"
#include "luma.h"

#include <darkroom/context.h>
#include <darkroom/error.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

namespace darkroom {

namespace {

// Blends pixel i with neighbour j by t. With alpha the colours are mixed
// premultiplied (straight alpha in and out), as a filtered fetch of
// premultiplied colour would; equal alphas reduce to a plain lerp.
struct ColourPlanes {
    const float *r, *g, *b, *a;
    float *outR, *outG, *outB, *outA;

    void copy(std::size_t i) const {
        outR[i] = r[i];
        outG[i] = g[i];
        outB[i] = b[i];
        if (a) outA[i] = a[i];
    }

    void blend(std::size_t i, std::size_t j, float t) const {
        if (!a || a[i] == a[j]) {
            outR[i] = r[i] + t * (r[j] - r[i]);
            outG[i] = g[i] + t * (g[j] - g[i]);
            outB[i] = b[i] + t * (b[j] - b[i]);
            if (a) outA[i] = a[i];
            return;
        }
        const float wi = a[i] * (1.0f - t), wj = a[j] * t;
        const float alpha = wi + wj;  // > 0: both alphas are > 0 (blendable)
        outR[i] = (wi * r[i] + wj * r[j]) / alpha;
        outG[i] = (wi * g[i] + wj * g[j]) / alpha;
        outB[i] = (wi * b[i] + wj * b[j]) / alpha;
        outA[i] = alpha;
    }
};

// The pixels of a band of rows that need a decision, gathered until there are
// enough to fill vectors, then decided together (decideList) and blended. A
// few thousand entries at most: the buffers stay in the cache and never grow
// with the image.
class EdgeBatch {
public:
    EdgeBatch(const fxaa::LumaPlane& plane, const fxaa::Settings& s, const ColourPlanes& planes)
        : plane_(plane), s_(s), planes_(planes),
          vectorised_(std::size_t(plane.width) * std::size_t(plane.height) <= std::size_t(INT32_MAX)) {
        const std::size_t capacity = kFlush + std::size_t(plane.width) + 64;  // 64: flatSpan's vector stores
        xs_.resize(capacity);
        ys_.resize(capacity);
        amount_.resize(capacity);
        partner_.resize(capacity);
    }

    // Pixel (x, y): kept as it is when not blendable (NaN luma), else queued.
    void add(int x, int y) {
        const std::size_t i = index(x, y);
        if (std::isnan(plane_.luma[i])) {
            planes_.copy(i);
            return;
        }
        xs_[count_] = x;
        ys_[count_] = y;
        ++count_;
    }

    // Row y, 0 < y < height - 1, from x = 1: flatSpan copies the flat pixels
    // and queues the others. Returns where it stopped (1 when the row is
    // shorter than a vector).
    int addInterior(const fxaa::ColourRows& rows, int y) {
        const std::size_t before = count_;
        const int x = fxaa::flatSpan(plane_, s_, rows, y, 1, plane_.width - 1, xs_.data(), count_);
        std::fill(ys_.begin() + std::ptrdiff_t(before), ys_.begin() + std::ptrdiff_t(count_), y);
        return std::max(x, 1);
    }

    // Decides and writes the queued pixels once a row has made them enough
    // (or always, when `all`).
    void flush(bool all) {
        if (count_ == 0 || (!all && count_ < kFlush)) return;
        if (vectorised_) {
            fxaa::decideList(plane_, s_, xs_.data(), ys_.data(), count_, amount_.data(), partner_.data());
            for (std::size_t k = 0; k < count_; ++k)
                write(index(xs_[k], ys_[k]), std::size_t(partner_[k]), amount_[k]);
        } else {
            // Too large for decideList's int32 indices: the per-pixel decision.
            for (std::size_t k = 0; k < count_; ++k) {
                const int x = xs_[k], y = ys_[k];
                const fxaa::Blend d = fxaa::decide(plane_, x, y, s_);
                const int nx = std::clamp(x + d.dx, 0, plane_.width - 1);
                const int ny = std::clamp(y + d.dy, 0, plane_.height - 1);
                write(index(x, y), index(nx, ny), d.amount);
            }
        }
        count_ = 0;
    }

private:
    static constexpr std::size_t kFlush = 2048;

    std::size_t index(int x, int y) const { return std::size_t(y) * std::size_t(plane_.width) + std::size_t(x); }

    // Pixel i takes `amount` of its neighbour j, unless there is nothing to
    // take or j is not blendable.
    void write(std::size_t i, std::size_t j, float amount) const {
        if (amount > 0.0f && j != i && !std::isnan(plane_.luma[j]))
            planes_.blend(i, j, amount);
        else
            planes_.copy(i);
    }

    const fxaa::LumaPlane& plane_;
    const fxaa::Settings& s_;
    const ColourPlanes& planes_;
    const bool vectorised_;
    std::vector<std::int32_t> xs_, ys_;
    std::vector<float> amount_;
    std::vector<std::int32_t> partner_;
    std::size_t count_ = 0;
};

}  // namespace

std::vector<std::pair<int, std::string>> Fxaa::presetChoices() {
    std::vector<std::pair<int, std::string>> out;
    const auto& all = fxaa::presets();
    for (std::size_t i = 0; i < all.size(); ++i) out.emplace_back(int(i), all[i].name);
    return out;
}

int Fxaa::presetIndex(const std::string& name) {
    const auto& all = fxaa::presets();
    for (std::size_t i = 0; i < all.size(); ++i)
        if (all[i].name == name) return int(i);
    return -1;
}

void Fxaa::execute(Context& ctx) {
    const BufferPtr in = ctx.get(image_);
    fxaa::Settings s;
    s.preset = &fxaa::presets().at(std::size_t(ctx.get(preset_)));
    s.subpix = float(ctx.get(subpix_));
    s.edgeThreshold = float(ctx.get(edgeThreshold_));
    s.edgeThresholdMin = float(ctx.get(edgeThresholdMin_));
    if (!(s.subpix >= 0.0f && s.subpix <= 1.0f) || !(s.edgeThreshold >= 0.0f && s.edgeThreshold <= 1.0f) ||
        !(s.edgeThresholdMin >= 0.0f && s.edgeThresholdMin <= 1.0f))
        throw Error("subpix, edgeThreshold and edgeThresholdMin must lie in [0, 1]");

    const int w = in->width(), h = in->height();
    const std::size_t rowLength = std::size_t(w);
    const float* r = in->requireFloat("R");
    const float* g = in->requireFloat("G");
    const float* b = in->requireFloat("B");
    const float* a = in->hostFloat("A");  // optional; a uint32 "A" is just passed through

    // Pass 1: luma of every pixel, NaN where it must not be blended. A plane
    // from the host's pool (no page faults when the pass runs again), not
    // filled: every entry is written below.
    const auto lumaPlane = ctx.allocate(w, h, {"luma"}, Fill::None);
    float* const luma = lumaPlane->writeFloat("luma");
    ctx.parallelFor(0, h, 16, [&](int y0, int y1) {
        const std::size_t begin = std::size_t(y0) * rowLength, end = std::size_t(y1) * rowLength;
        fxaa::computeLuma(r, g, b, a, luma, fxaa::lumaSpan(r, g, b, a, luma, begin, end), end);
    });
    ctx.progress(0.3);

    // Only the colour is new; every other channel is shared with the input.
    // Pass 2 writes every pixel of it.
    std::vector<ChannelDesc> fresh{"R", "G", "B"};
    if (a) fresh.push_back("A");
    auto out = ctx.derive(in, fresh, Fill::None);
    const ColourPlanes planes{r, g, b, a, out->writeFloat("R"), out->writeFloat("G"), out->writeFloat("B"),
                              a ? out->writeFloat("A") : nullptr};
    const fxaa::LumaPlane plane{luma, w, h};

    // Pass 2: each pixel reads the luma around it and writes only itself, so
    // rows are independent and the result does not depend on the split.
    // Inside the image, a vector of pixels at a time leaves the flat ones as
    // they are; only the others (and the border) are decided, a batch of them
    // together.
    const fxaa::ColourRows rows{{r, g, b, a}, {planes.outR, planes.outG, planes.outB, planes.outA}};
    ctx.parallelFor(0, h, 8, [&](int y0, int y1) {
        EdgeBatch batch(plane, s, planes);
        for (int y = y0; y < y1; ++y) {
            int x = 0;
            if (y > 0 && y < h - 1 && w > 2) {
                batch.add(0, y);
                x = batch.addInterior(rows, y);
            }
            for (; x < w; ++x) batch.add(x, y);
            batch.flush(false);
        }
        batch.flush(true);
    });
    ctx.progress(1.0);
    ctx.set(result_, out);
}

}  // namespace darkroom
