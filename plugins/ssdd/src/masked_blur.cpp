#include "masked_blur.h"

#include <darkroom/view_geometry.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace darkroom::passes {

namespace {

std::vector<float> gaussianKernel(double sigma, int radius) {
    std::vector<float> k(std::size_t(2 * radius + 1));
    for (int i = -radius; i <= radius; ++i)
        k[std::size_t(i + radius)] = float(std::exp(-0.5 * double(i) * double(i) / (sigma * sigma)));
    // No normalisation needed: the weights are divided out per pixel.
    return k;
}

// dst[x] += weight * src[x + shift] for every x where x + shift is inside.
inline void addShifted(float* dst, const float* src, int width, int shift, float weight) {
    const int x0 = std::max(0, -shift), x1 = std::min(width, width - shift);
    for (int x = x0; x < x1; ++x) dst[x] += weight * src[x + shift];
}

}  // namespace

std::vector<float> maskedGaussianDepth(Context& ctx, const float* depth, int w, int h, double sigma) {
    const std::size_t n = std::size_t(w) * std::size_t(h);
    // Blurring D - reference instead of D keeps float sums accurate for
    // scenes far from the camera.
    float reference = std::numeric_limits<float>::infinity();
    for (std::size_t i = 0; i < n; ++i)
        if (darkroom::isSurface(depth[i])) reference = std::min(reference, depth[i]);
    std::vector<float> out(n, std::numeric_limits<float>::quiet_NaN());
    if (!std::isfinite(reference)) return out;

    // Beyond the image size a wider kernel changes nothing but the cost.
    const int radius = int(std::min(std::ceil(3.0 * sigma), double(std::max(w, h))));
    const std::vector<float> k = gaussianKernel(sigma, radius);
    std::vector<float> hd(n), hm(n);  // horizontally blurred masked depth and mask

    ctx.parallelFor(0, h, 4, [&](int y0, int y1) {
        std::vector<float> md(static_cast<std::size_t>(w)), mm(static_cast<std::size_t>(w));
        for (int y = y0; y < y1; ++y) {
            const float* row = depth + std::size_t(y) * w;
            for (int x = 0; x < w; ++x) {
                const bool s = darkroom::isSurface(row[x]);
                md[std::size_t(x)] = s ? row[x] - reference : 0.0f;
                mm[std::size_t(x)] = s ? 1.0f : 0.0f;
            }
            float* od = hd.data() + std::size_t(y) * w;
            float* om = hm.data() + std::size_t(y) * w;
            for (int j = -radius; j <= radius; ++j) {
                addShifted(od, md.data(), w, j, k[std::size_t(j + radius)]);
                addShifted(om, mm.data(), w, j, k[std::size_t(j + radius)]);
            }
        }
    });
    if (ctx.cancelled()) return out;
    ctx.parallelFor(0, h, 4, [&](int y0, int y1) {
        std::vector<float> ad(static_cast<std::size_t>(w)), am(static_cast<std::size_t>(w));
        for (int y = y0; y < y1; ++y) {
            std::fill(ad.begin(), ad.end(), 0.0f);
            std::fill(am.begin(), am.end(), 0.0f);
            for (int j = std::max(-radius, -y); j <= std::min(radius, h - 1 - y); ++j) {
                const float g = k[std::size_t(j + radius)];
                const float* sd = hd.data() + std::size_t(y + j) * w;
                const float* sm = hm.data() + std::size_t(y + j) * w;
                for (int x = 0; x < w; ++x) {
                    ad[std::size_t(x)] += g * sd[x];
                    am[std::size_t(x)] += g * sm[x];
                }
            }
            const float* row = depth + std::size_t(y) * w;
            float* o = out.data() + std::size_t(y) * w;
            for (int x = 0; x < w; ++x)
                // A surface pixel weighs itself with 1, so am >= 1 there.
                if (darkroom::isSurface(row[x])) o[x] = ad[std::size_t(x)] / am[std::size_t(x)] + reference;
        }
    });
    return out;
}

}  // namespace darkroom::passes
