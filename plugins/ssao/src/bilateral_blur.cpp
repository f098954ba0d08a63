#include "bilateral_blur.h"

#include <cmath>
#include <vector>

namespace darkroom::ssao {

namespace {

void blurPass(const PixelGeometry& g, const AoSettings& s, const std::vector<float>& spatial, int dx, int dy,
              Context& ctx, const float* src, float* dst) {
    const int radius = int(spatial.size()) - 1;
    ctx.parallelFor(0, g.height(), 8, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < g.width(); ++x) {
                const std::size_t i = g.index(x, y);
                if (!g.valid[i]) {
                    dst[i] = src[i];
                    continue;
                }
                const V3f p = g.points[i];
                const V3f nrm = g.normal[i];
                const float sigma = 0.1f * s.worldRadius(g, p.z);
                const float inv = sigma > 0 ? 1.0f / (sigma * sigma) : 0.0f;
                float sum = spatial[0] * src[i], weight = spatial[0];
                for (int k = -radius; k <= radius; ++k) {
                    if (k == 0) continue;
                    const int qx = x + k * dx, qy = y + k * dy;
                    if (qx < 0 || qy < 0 || qx >= g.width() || qy >= g.height()) continue;
                    const std::size_t q = g.index(qx, qy);
                    if (!g.valid[q]) continue;
                    const float plane = dot(nrm, g.points[q] - p);
                    const float w = spatial[std::size_t(std::abs(k))] * std::exp(-plane * plane * inv);
                    sum += w * src[q];
                    weight += w;
                }
                dst[i] = sum / weight;
            }
    });
}

}  // namespace

void bilateralBlur(const PixelGeometry& g, const AoSettings& s, int radius, Context& ctx, float* ao) {
    if (radius <= 0) return;
    std::vector<float> spatial(std::size_t(radius) + 1);
    const float sigma = 0.5f * float(radius);
    for (int k = 0; k <= radius; ++k) spatial[std::size_t(k)] = std::exp(-0.5f * float(k * k) / (sigma * sigma));
    std::vector<float> tmp(g.points.size());
    blurPass(g, s, spatial, 1, 0, ctx, ao, tmp.data());
    blurPass(g, s, spatial, 0, 1, ctx, tmp.data(), ao);
}

}  // namespace darkroom::ssao
