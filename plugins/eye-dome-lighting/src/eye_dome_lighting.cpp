#include "eye_dome_lighting.h"

#include <darkroom/depth_input.h>
#include <darkroom/error.h>
#include <darkroom/view_geometry.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace darkroom {

namespace {

struct Offset {
    int dx, dy;
};

// The 8 neighbours on a circle of radius r (VTK's directions 2πk/8), rounded
// to pixels; at least one pixel away.
std::vector<Offset> ring(double r) {
    std::vector<Offset> o;
    for (int k = 0; k < 8; ++k) {
        const double a = 2.0 * std::numbers::pi * k / 8.0;
        int dx = int(std::lround(r * std::cos(a))), dy = int(std::lround(r * std::sin(a)));
        if (dx == 0 && dy == 0) dx = k < 4 ? 1 : -1;
        o.push_back({dx, dy});
    }
    return o;
}

}  // namespace

void EyeDomeLighting::execute(Context& ctx) {
    const BufferPtr in = ctx.get(image_);
    const int w = in->width(), h = in->height();
    const std::size_t n = in->pixelCount();
    const float* z = requireDepth(*in);  // no camera needed: EDL works on log depth
    const double strength = ctx.get(strength_), radius = ctx.get(radius_);
    const int scales = int(ctx.get(scales_));

    // log2 depth; NaN where there is no surface (background, non-positive depth).
    std::vector<float> logDepth(n);
    ctx.parallelFor(0, h, 32, [&](int y0, int y1) {
        for (std::size_t i = std::size_t(y0) * w; i < std::size_t(y1) * w; ++i)
            logDepth[i] = isSurface(z[i]) && z[i] > 0 ? std::log2(z[i]) : std::numeric_limits<float>::quiet_NaN();
    });

    std::vector<std::vector<Offset>> rings;
    std::vector<double> weights;
    double total = 0;
    for (int s = 0; s < scales; ++s) {
        rings.push_back(ring(radius * std::ldexp(1.0, s)));
        weights.push_back(std::ldexp(1.0, -s));
        total += weights.back();
    }
    for (double& wt : weights) wt /= total;

    const float* rgbIn[3] = {in->hostFloat("R"), in->hostFloat("G"), in->hostFloat("B")};
    const bool shadeColour = ctx.get(apply_) && rgbIn[0] && rgbIn[1] && rgbIn[2];
    std::vector<ChannelDesc> fresh{"EDL"};
    if (shadeColour) fresh.insert(fresh.end(), {"R", "G", "B"});
    auto out = ctx.derive(in, fresh, Fill::None);
    float* edl = out->writeFloat("EDL");
    float* rgb[3] = {nullptr, nullptr, nullptr};
    if (shadeColour)
        for (int c = 0; c < 3; ++c) rgb[c] = out->writeFloat(fresh[std::size_t(c) + 1].name);

    const float gain = float(kGain * strength);
    ctx.parallelFor(0, h, 16, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < w; ++x) {
                const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
                const float l = logDepth[i];
                double shade = 1.0;
                if (!std::isnan(l)) {
                    shade = 0;
                    for (std::size_t s = 0; s < rings.size(); ++s) {
                        // Neighbours beyond the border are the border pixel (clamp to edge, as VTK's texture).
                        float response = 0;
                        for (const Offset& o : rings[s]) {
                            const int qx = std::clamp(x + o.dx, 0, w - 1), qy = std::clamp(y + o.dy, 0, h - 1);
                            const float lq = logDepth[std::size_t(qy) * std::size_t(w) + std::size_t(qx)];
                            // Background behind the pixel never shades it (NaN fails the test).
                            if (lq < l) response += l - lq;
                        }
                        shade += weights[s] * std::exp(-gain * response / 8.0f);
                    }
                }
                edl[i] = float(shade);
                if (shadeColour)
                    for (int c = 0; c < 3; ++c) rgb[c][i] = std::isnan(l) ? rgbIn[c][i] : rgbIn[c][i] * float(shade);
            }
    });
    ctx.progress(1.0);
    ctx.set(result_, out);
}

}  // namespace darkroom
