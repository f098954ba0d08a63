#pragma once
// Helpers shared by the ao and normals sweeps: region masks restricted to
// geometry, bilinear upsampling of one channel, and side-by-side failure
// panels. Header-only so the sweeps stay one file each.
#include <darkroom/buffer.h>
#include <darkroom/accuracy/metrics.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace darkroom::accuracy::ao {

// The three regions of every metric row, each restricted to pixels with
// finite depth: background is excluded everywhere, because both the passes and
// the references write a fixed value there (AO 1, normals NaN) and would only
// dilute the statistics.
struct Regions {
    std::vector<std::uint8_t> all, edge, interior;
    const std::uint8_t* get(const std::string& region) const {
        if (region == "edge") return edge.data();
        if (region == "interior") return interior.data();
        return all.data();
    }
};

inline Regions regions(const Buffer& gbuffer) {
    const metrics::EdgeMasks m = metrics::edgeMasks(gbuffer);
    const float* z = gbuffer.requireFloat("Z");
    const std::size_t n = gbuffer.pixelCount();
    Regions r;
    r.all.assign(n, 0);
    r.edge.assign(n, 0);
    r.interior = m.interior;
    for (std::size_t i = 0; i < n; ++i) {
        r.all[i] = std::isfinite(z[i]) ? 1 : 0;
        r.edge[i] = (r.all[i] && m.edge[i]) ? 1 : 0;
    }
    return r;
}

inline const char* const kRegions[] = {"all", "edge", "interior"};

// Channel `channel` of `src` resampled to w x h with pixel centres aligned
// ((x + 0.5) * src.w / w - 0.5) and clamped at the border: what a pipeline
// computing AO at reduced resolution does before multiplying it in.
inline std::shared_ptr<WritableBuffer> upsampleBilinear(const Buffer& src, const std::string& channel, int w,
                                                        int h) {
    auto out = makeCpuBuffer(w, h, {{channel, ChannelType::Float32}});
    const float* in = src.requireFloat(channel);
    float* o = out->writeFloat(channel);
    const int sw = src.width(), sh = src.height();
    const double fx = double(sw) / w, fy = double(sh) / h;
    for (int y = 0; y < h; ++y) {
        const double sy = std::clamp((y + 0.5) * fy - 0.5, 0.0, double(sh - 1));
        const int y0 = int(sy), y1 = std::min(y0 + 1, sh - 1);
        const float ty = float(sy - y0);
        for (int x = 0; x < w; ++x) {
            const double sx = std::clamp((x + 0.5) * fx - 0.5, 0.0, double(sw - 1));
            const int x0 = int(sx), x1 = std::min(x0 + 1, sw - 1);
            const float tx = float(sx - x0);
            const float a = in[std::size_t(y0) * sw + x0] * (1 - tx) + in[std::size_t(y0) * sw + x1] * tx;
            const float b = in[std::size_t(y1) * sw + x0] * (1 - tx) + in[std::size_t(y1) * sw + x1] * tx;
            o[std::size_t(y) * w + x] = a * (1 - ty) + b * ty;
        }
    }
    return out;
}

// A panel of `count` equally sized w x h tiles side by side, 2 px apart, with
// channels R, G, B (mid grey between tiles). tile(i, x, y, rgb) fills one pixel.
template <class TileFn>
std::shared_ptr<WritableBuffer> panel(int w, int h, int count, TileFn&& tile) {
    constexpr int kGap = 2;
    const int pw = count * w + (count - 1) * kGap;
    auto out = makeCpuBuffer(pw, h, {{"R", ChannelType::Float32}, {"G", ChannelType::Float32},
                                     {"B", ChannelType::Float32}});
    float* c[3] = {out->writeFloat("R"), out->writeFloat("G"), out->writeFloat("B")};
    for (int y = 0; y < h; ++y)
        for (int px = 0; px < pw; ++px) {
            const int i = px / (w + kGap), x = px % (w + kGap);
            float rgb[3] = {0.5f, 0.5f, 0.5f};
            if (x < w) tile(i, x, y, rgb);
            for (int k = 0; k < 3; ++k) c[k][std::size_t(y) * pw + px] = std::clamp(rgb[k], 0.0f, 1.0f);
        }
    return out;
}

}  // namespace darkroom::accuracy::ao
