#pragma once
// Parts shared by the anti-aliasing (sweep_fxaa.cpp) and depth-of-field
// (sweep_dof.cpp) sweeps: both compare a colour image (R, G, B) with a
// ray-traced colour reference, over all / edge / interior pixels, and both
// write small side-by-side failure panels.
#include "harness.h"

#include <darkroom/buffer.h>
#include <darkroom/colormap.h>
#include <darkroom/accuracy/metrics.h>
#include <darkroom/accuracy/reference.h>
#include <darkroom/accuracy/stress_scenes.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace darkroom::accuracy::aa {

inline const char* const kRgb[3] = {"R", "G", "B"};

// What every reference and capture of a stress scene needs: depth and the
// colour field (plus object ids for the edge masks, on the 1-spp capture).
inline CaptureRequest fieldRequest(const stress::StressScene& s, bool withIds) {
    CaptureRequest r;
    r.scalars = {s.colorField};
    r.objectId = withIds;
    return r;
}

// reference::colorMapShader with exactly the map, range and background of
// Harness::colorize.
inline reference::SampleShader sceneShader(const stress::StressScene& s) {
    static const ColorMapData viridis = loadColorMap("viridis");
    return reference::colorMapShader(
        s.colorField, viridis, s.fieldMin, s.fieldMax,
        Color{Harness::kBackground[0], Harness::kBackground[1], Harness::kBackground[2], 1.0f});
}

// One wall-clock run, in milliseconds (for the references, too slow to
// repeat).
inline double timeOnceMs(const std::function<void()>& work) {
    const auto t0 = std::chrono::steady_clock::now();
    work();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// The mean over R, G and B of one metric, over one region.
struct RgbError {
    double rmse = 0, psnr = 0, ssim = 0;
};

inline RgbError rgbError(const Buffer& image, const Buffer& ref, const std::uint8_t* mask) {
    RgbError e;
    for (const char* c : kRgb) {
        e.rmse += metrics::rmse(image, ref, c, mask).value / 3.0;
        e.psnr += metrics::psnr(image, ref, c, 1.0, mask).value / 3.0;
        e.ssim += metrics::ssim(image, ref, c, 1.0, mask).value / 3.0;
    }
    return e;
}

// Writes rmse, psnr, ssim for all / edge / interior pixels as rows copied from
// `base` (which holds everything but region, metric and value). Returns the
// RMSE over all pixels.
inline double addErrorRows(Csv& csv, Row base, const Buffer& image, const Buffer& ref,
                           const metrics::EdgeMasks& masks) {
    const RgbError all = rgbError(image, ref, nullptr);
    const std::array<std::pair<const char*, RgbError>, 3> regions = {
        std::pair{"all", all}, std::pair{"edge", rgbError(image, ref, masks.edge.data())},
        std::pair{"interior", rgbError(image, ref, masks.interior.data())}};
    for (const auto& [region, e] : regions) {
        base.region = region;
        for (const auto& [metric, value] :
             std::array<std::pair<const char*, double>, 3>{{{"rmse", e.rmse}, {"psnr", e.psnr}, {"ssim", e.ssim}}}) {
            base.metric = metric;
            base.value = value;
            csv.add(base);
        }
    }
    return all.rmse;
}

// A timing-only row (capture, reference): metric "ms_per_mpix", so charts of
// error metrics never pick it up.
inline void addTimeRow(Csv& csv, Row base, double msPerMpix) {
    base.msPerMpix = msPerMpix;
    base.region = "all";
    base.metric = "ms_per_mpix";
    base.value = msPerMpix;
    csv.add(base);
}

// |a - b| averaged over R, G, B, scaled by `gain` and clamped to 1, as grey.
inline std::shared_ptr<WritableBuffer> errorImage(const Buffer& a, const Buffer& b, float gain) {
    auto out = makeCpuBuffer(a.width(), a.height(), {{"R"}, {"G"}, {"B"}});
    const std::size_t n = a.pixelCount();
    std::vector<float> e(n, 0.0f);
    for (const char* c : kRgb) {
        const float* pa = a.requireFloat(c);
        const float* pb = b.requireFloat(c);
        for (std::size_t i = 0; i < n; ++i) e[i] += std::abs(pa[i] - pb[i]) / 3.0f;
    }
    for (const char* c : kRgb) {
        float* p = out->writeFloat(c);
        for (std::size_t i = 0; i < n; ++i) p[i] = std::min(1.0f, gain * e[i]);
    }
    return out;
}

// Side-by-side panels of the centre crop (at most 128 px square) of each
// image, magnified with nearest-neighbour so each panel is about 256 px and
// single pixels stay visible, separated by white gaps. Written as
// <name>.png into the harness's image folder; returns the path or "".
inline std::string writePanel(const Harness& harness, const std::vector<const Buffer*>& images,
                              const std::string& name) {
    if (harness.options().imageDir.empty() || images.empty()) return "";
    const int w = images[0]->width(), h = images[0]->height();
    const int crop = std::min({w, h, 128});
    const int zoom = std::max(1, 256 / crop);
    const int x0 = (w - crop) / 2, y0 = (h - crop) / 2;
    constexpr int kGap = 4;
    const int side = crop * zoom;
    const int width = int(images.size()) * side + (int(images.size()) - 1) * kGap;
    auto out = makeCpuBuffer(width, side, {{"R"}, {"G"}, {"B"}});
    for (const char* c : kRgb) std::fill_n(out->writeFloat(c), out->pixelCount(), 1.0f);
    for (std::size_t k = 0; k < images.size(); ++k)
        for (const char* c : kRgb) {
            const float* src = images[k]->requireFloat(c);
            float* dst = out->writeFloat(c);
            for (int y = 0; y < side; ++y)
                for (int x = 0; x < side; ++x)
                    dst[std::size_t(y) * width + std::size_t(k) * (side + kGap) + x] =
                        src[std::size_t(y0 + y / zoom) * w + std::size_t(x0 + x / zoom)];
        }
    return harness.writePicture(*out, {"R", "G", "B"}, name);
}

}  // namespace darkroom::accuracy::aa
