#include "fxaa_filter.h"

#include "fxaa_kernel.h"
#include "fxaa_presets.h"
#include "luma.h"

#include <darkroom/context.h>
#include <darkroom/error.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>

namespace darkroom {

namespace {

bool isColour(const ChannelDesc& c) {
    return c.type == ChannelType::Float32 && (c.name == "R" || c.name == "G" || c.name == "B" || c.name == "A");
}

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

PortList Fxaa::ports() const {
    PortList p;
    p.imageIn("image", "Linear colour R, G, B (A optional: pixels with A <= 0 are background)",
              {"R", "G", "B"});
    p.enumIn("preset", fxaa::presetNames(), "12",
             "FXAA 3.11 quality preset: 10-15 medium dither (10 fastest), 20-29 less dither and "
             "longer edge searches, 39 no dither (slowest); the last digit is the search length");
    p.floatIn("subpix", 0.75, 0.0, 1.0,
              "Sub-pixel aliasing removal: 0 off, 0.25 sharper, 0.75 FXAA's default, 1 softest");
    p.floatIn("edgeThreshold", 0.166, 0.0, 1.0,
              "Local luma contrast needed to process a pixel, relative to the brightest pixel of "
              "its cross: 0.333 too little, 0.166 default, 0.125 high quality, 0.063 overkill");
    p.floatIn("edgeThresholdMin", 0.0833, 0.0, 1.0,
              "Absolute luma contrast below which dark pixels are skipped: 0.0833 default, "
              "0.0625 high quality, 0.0312 visible limit");
    p.imageOut("image",
               "Anti-aliased R, G, B (and A, blended with the same weight); every other channel "
               "passes through unchanged; NaN or transparent pixels are never mixed into others",
               {"R", "G", "B"});
    return p;
}

void Fxaa::execute(Context& ctx) {
    const BufferPtr in = ctx.requireImage("image");
    const std::string node = "FXAA '" + ctx.nodeName() + "'";
    fxaa::Settings s;
    try {
        s.preset = &fxaa::preset(ctx.getString("preset"));
    } catch (const Error& e) {
        throw Error(node + ": " + e.what());
    }
    s.subpix = float(ctx.getFloat("subpix"));
    s.edgeThreshold = float(ctx.getFloat("edgeThreshold"));
    s.edgeThresholdMin = float(ctx.getFloat("edgeThresholdMin"));
    if (!(s.subpix >= 0.0f && s.subpix <= 1.0f) || !(s.edgeThreshold >= 0.0f && s.edgeThreshold <= 1.0f) ||
        !(s.edgeThresholdMin >= 0.0f && s.edgeThresholdMin <= 1.0f))
        throw Error(node + ": subpix, edgeThreshold and edgeThresholdMin must lie in [0, 1]");

    const int w = in->width(), h = in->height();
    const std::size_t rowLength = std::size_t(w);
    const float* r = in->requireFloat("R");
    const float* g = in->requireFloat("G");
    const float* b = in->requireFloat("B");
    const float* a = in->hostFloat("A");  // optional; a uint32 "A" is just passed through

    // Pass 1: luma of every pixel, NaN where it must not be blended.
    // Not value-initialised: every entry is written below, and on large
    // images zeroing would be a pass over memory of its own.
    const std::unique_ptr<float[]> luma(new float[in->pixelCount()]);
    ctx.parallelFor(0, h, 16, [&](int y0, int y1) {
        fxaa::computeLuma(r, g, b, a, luma.get(), std::size_t(y0) * rowLength, std::size_t(y1) * rowLength);
    });
    if (ctx.cancelled()) return;
    ctx.progress(0.3);

    auto out = ctx.allocate(w, h, in->channels());
    out->metadata() = in->metadata();
    const ColourPlanes planes{r, g, b, a, out->hostFloat("R"), out->hostFloat("G"), out->hostFloat("B"),
                              a ? out->hostFloat("A") : nullptr};
    const fxaa::LumaPlane plane{luma.get(), w, h};

    // Pass 2: each pixel reads the luma around it and writes only itself, so
    // rows are independent and the result does not depend on the split.
    ctx.parallelFor(0, h, 8, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < w; ++x) {
                const std::size_t i = std::size_t(y) * rowLength + std::size_t(x);
                if (std::isnan(luma[i])) {
                    planes.copy(i);  // NaN or transparent: kept as it is
                    continue;
                }
                const fxaa::Blend d = fxaa::decide(plane, x, y, s);
                const int nx = std::clamp(x + d.dx, 0, w - 1), ny = std::clamp(y + d.dy, 0, h - 1);
                const std::size_t j = std::size_t(ny) * rowLength + std::size_t(nx);
                if (d.amount > 0.0f && j != i && !std::isnan(luma[j]))
                    planes.blend(i, j, d.amount);
                else
                    planes.copy(i);
            }
    });
    if (ctx.cancelled()) return;

    // Every other channel passes through (row chunks in parallel: on large
    // G-buffers the copies cost as much as the filter).
    for (const auto& c : in->channels()) {
        if (isColour(c) && (c.name != "A" || a)) continue;
        const std::size_t bytes = 4;
        const void* src = c.type == ChannelType::UInt32 ? static_cast<const void*>(in->hostUInt(c.name))
                                                        : static_cast<const void*>(in->hostFloat(c.name));
        void* dst = c.type == ChannelType::UInt32 ? static_cast<void*>(out->hostUInt(c.name))
                                                  : static_cast<void*>(out->hostFloat(c.name));
        ctx.parallelFor(0, h, 64, [&](int y0, int y1) {
            const std::size_t begin = std::size_t(y0) * rowLength * bytes;
            std::memcpy(static_cast<char*>(dst) + begin, static_cast<const char*>(src) + begin,
                        std::size_t(y1 - y0) * rowLength * bytes);
        });
    }
    if (ctx.cancelled()) return;
    ctx.progress(1.0);
    ctx.setOutput("image", BufferPtr(std::move(out)));
}

}  // namespace darkroom
