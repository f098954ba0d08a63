#include "fxaa.h"

#include "fxaa_kernel.h"
#include "fxaa_presets.h"
#include "fxaa_simd.h"
#include "luma.h"

#include <darkroom/context.h>
#include <darkroom/error.h>

#include <algorithm>
#include <cmath>
#include <memory>

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
    auto filterPixel = [&](int x, int y) {
        const std::size_t i = std::size_t(y) * rowLength + std::size_t(x);
        if (std::isnan(luma[i])) {
            planes.copy(i);  // NaN or transparent: kept as it is
            return;
        }
        const fxaa::Blend d = fxaa::decide(plane, x, y, s);
        const int nx = std::clamp(x + d.dx, 0, w - 1), ny = std::clamp(y + d.dy, 0, h - 1);
        const std::size_t j = std::size_t(ny) * rowLength + std::size_t(nx);
        if (d.amount > 0.0f && j != i && !std::isnan(luma[j]))
            planes.blend(i, j, d.amount);
        else
            planes.copy(i);
    };
    const fxaa::ColourRows rows{{r, g, b, a}, {planes.outR, planes.outG, planes.outB, planes.outA}};
    ctx.parallelFor(0, h, 8, [&](int y0, int y1) {
        // Inside the image, a vector of pixels at a time leaves the flat ones
        // as they are; only the others go through the edge search.
        std::vector<std::uint8_t> needsDecision(rowLength);
        for (int y = y0; y < y1; ++y) {
            int x = 0;
            if (y > 0 && y < h - 1 && w > 2) {
                filterPixel(0, y);
                x = fxaa::flatSpan(plane, s, rows, y, 1, w - 1, needsDecision.data());
                for (int k = 1; k < x; ++k)
                    if (needsDecision[std::size_t(k)]) filterPixel(k, y);
                x = std::max(x, 1);
            }
            for (; x < w; ++x) filterPixel(x, y);
        }
    });
    ctx.progress(1.0);
    ctx.set(result_, out);
}

}  // namespace darkroom
