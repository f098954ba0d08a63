#include "ssao.h"

#include "ao_estimators.h"
#include "bilateral_blur.h"
#include "depth_pyramid.h"
#include "finish.h"
#include "frame.h"
#include "half_resolution.h"

#include <darkroom/depth_input.h>
#include <darkroom/error.h>

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

namespace darkroom {
namespace {

// Defaults of LineAO and PointAO (README: how they were chosen).
constexpr int kLineAoLevels = 3, kPointAoLevels = 3;
constexpr float kLineAoZone = 0.5f, kPointAoZone = 1.0f;
constexpr float kLineAoStrength = 5.0f, kPointAoStrength = 5.0f;  // the papers use 1-3 with screen-space radii; 5 halves the corner bias (README)

using RowEstimator = std::function<void(int y, const std::int32_t* xs, int count, float* ao)>;

// Runs `estimate` over the image into `raw` (every pixel, or at half
// resolution the even pixels into `tmp`, then the filled rows), padding of
// both planes set to 1.
void estimateImage(const ssao::Frame& g, bool half, const RowEstimator& estimate, float* raw, float* tmp, Context& ctx) {
    const int h = g.height();
    if (!half) {
        ctx.parallelFor(0, h, 4, [&](int y0, int y1) {
            g.fillPadding(raw, y0, y1, 1.0f);
            if (tmp) g.fillPadding(tmp, y0, y1, 1.0f);
            for (int y = y0; y < y1; ++y) estimate(y, nullptr, 0, raw);
        });
        return;
    }
    // Even rows at even x into tmp, then every row of raw from them.
    std::vector<std::int32_t> even;
    for (int x = 0; x < g.width(); x += 2) even.push_back(x);
    ctx.parallelFor(0, (h + 1) / 2, 2, [&](int r0, int r1) {
        for (int r = r0; r < r1; ++r) {
            g.fillPadding(tmp, 2 * r, std::min(2 * r + 2, h), 1.0f);
            estimate(2 * r, even.data(), int(even.size()), tmp);
        }
    });
    ctx.parallelFor(0, h, 4, [&](int y0, int y1) {
        std::vector<std::int32_t> missing(std::size_t(g.width()));
        g.fillPadding(raw, y0, y1, 1.0f);
        for (int y = y0; y < y1; ++y) estimate(y, missing.data(), ssao::fillRow(g, y, tmp, raw, missing.data()), raw);
    });
}

}  // namespace

PortList Ssao::ports() const {
    return {image_,     method_,     geometry_, radius_, radiusUnits_, samples_, levels_,     zone_,
            strength_,  slices_,     steps_,    falloff_, bias_,       thickness_, intensity_, power_,
            seed_,      blurRadius_, resolution_, useNormals_, camera_.port(), result_};
}

ssao::AoSettings Ssao::settings(Context& ctx) const {
    using namespace ssao;
    AoSettings s;
    s.radius = float(ctx.get(radius_));
    s.radiusInImageHeight = ctx.get(radiusUnits_) == RadiusUnits::ImageHeight;
    s.samples = int(ctx.get(samples_));
    s.slices = int(ctx.get(slices_));
    s.steps = int(ctx.get(steps_));
    s.falloff = float(ctx.get(falloff_));
    s.bias = float(ctx.get(bias_));
    s.seed = std::uint32_t(ctx.get(seed_));
    s.geometry = ctx.get(geometry_) == GeometryKind::Points ? Geometry::Points : Geometry::Surface;
    s.thickness = float(ctx.get(thickness_));
    // LineAO and PointAO: 0 asks for the method's default.
    const bool points = ctx.get(method_) == Method::PointAO;
    s.levels = ctx.get(levels_) > 0 ? int(ctx.get(levels_)) : (points ? kPointAoLevels : kLineAoLevels);
    s.zone = ctx.get(zone_) > 0 ? float(ctx.get(zone_)) : (points ? kPointAoZone : kLineAoZone);
    s.strength = ctx.get(strength_) > 0 ? float(ctx.get(strength_)) : (points ? kPointAoStrength : kLineAoStrength);
    return s;
}

void Ssao::beginSequence(const SequenceInfo&) { camera_.beginSequence(); }

void Ssao::execute(Context& ctx) {
    using namespace ssao;
    const BufferPtr in = ctx.get(image_);
    const Camera camera = camera_.get(ctx, *in, requireDepth(*in));
    if (camera.projection == Camera::Projection::Perspective
            ? !(camera.fovYDegrees > 0 && camera.fovYDegrees < 180)
            : !(camera.viewHeight > 0))
        throw Error("the image's camera has an invalid field of view or view height");
    const int h = in->height();

    AoSettings s = settings(ctx);
    const float intensity = float(ctx.get(intensity_));
    const float power = float(ctx.get(power_));
    if (!(s.radius > 0) || !std::isfinite(s.radius)) throw Error("radius must be positive and finite");

    // Every pixel of AO is written below (1 where there is no surface).
    auto out = ctx.derive(in, {"AO"}, Fill::None);
    float* ao = out->writeFloat("AO");
    if (in->pixelCount() == 0) {
        ctx.set(result_, out);
        return;
    }

    const int blurRadius = int(ctx.get(blurRadius_));
    const Frame& g = frames_.get(*in, camera, ctx.get(useNormals_), blurRadius, ctx);
    ctx.progress(0.1);
    // Raw AO (and the blur's or the half resolution's intermediate) in
    // padded planes, whose padding reads as unoccluded: the blur reads past
    // the borders.
    const bool half = ctx.get(resolution_) == Resolution::Half;
    s.interleave = half;
    const auto scratch = g.allocatePlanes(ctx, blurRadius > 0 || half ? 2 : 1);
    float* raw = scratch->writeFloat("plane0");
    float* tmp = blurRadius > 0 || half ? scratch->writeFloat("plane1") : nullptr;
    g.fillPadding(raw, -g.padY, 0, 1.0f);
    g.fillPadding(raw, h, h + g.padY, 1.0f);
    if (tmp) {
        g.fillPadding(tmp, -g.padY, 0, 1.0f);
        g.fillPadding(tmp, h, h + g.padY, 1.0f);
    }
    const Method method = ctx.get(method_);
    const bool pyramidal = method == Method::LineAO || method == Method::PointAO || method == Method::Sao;
    // LineAO reads level l for its l-th radius; SAO's taps reach level
    // log2(radius in pixels) - 3, at most the image's own size.
    const Pyramid pyramid =
        pyramidal ? buildPyramid(g, method == Method::Sao ? Reduction::RotatedGrid : Reduction::Mean,
                                 method == Method::Sao ? 16 : s.levels - 1, ctx)
                  : Pyramid{};
    RowEstimator estimate;
    switch (method) {
    case Method::Hemisphere:
        estimate = [&](int y, const std::int32_t* xs, int n, float* dst) {
            xs ? hemisphereAOAt(g, s, y, xs, n, dst) : hemisphereAO(g, s, y, y + 1, dst);
        };
        break;
    case Method::Horizon:
        estimate = [&](int y, const std::int32_t* xs, int n, float* dst) {
            xs ? horizonAOAt(g, s, y, xs, n, dst) : horizonAO(g, s, y, y + 1, dst);
        };
        break;
    case Method::LineAO:
    case Method::PointAO:
        estimate = [&](int y, const std::int32_t* xs, int n, float* dst) { lineAO(g, pyramid, s, y, xs, n, dst); };
        break;
    case Method::Sao:
        estimate = [&](int y, const std::int32_t* xs, int n, float* dst) { saoAO(g, pyramid, s, y, xs, n, dst); };
        break;
    }
    estimateImage(g, half, estimate, raw, tmp, ctx);
    ctx.progress(0.8);
    if (blurRadius > 0) {
        const std::vector<float> spatial = blurWeights(blurRadius);
        ctx.parallelFor(0, h, 8, [&](int y0, int y1) { blurRows(g, s, spatial, false, y0, y1, raw, tmp); });
        ctx.parallelFor(0, h, 8, [&](int y0, int y1) { blurRows(g, s, spatial, true, y0, y1, tmp, raw); });
    }
    ctx.parallelFor(0, h, 64, [&](int y0, int y1) { finishRows(g, raw, intensity, power, y0, y1, ao); });
    ctx.progress(1.0);
    ctx.set(result_, out);
}

}  // namespace darkroom
