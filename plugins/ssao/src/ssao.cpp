#include "ssao.h"

#include "ao_estimators.h"
#include "bilateral_blur.h"
#include "frame.h"

#include <darkroom/error.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace darkroom {

PortList Ssao::ports() const {
    return {image_,     method_, geometry_,  radius_, radiusUnits_, samples_, slices_, steps_,    falloff_,
            bias_,      thickness_, intensity_, power_, seed_,      blurRadius_, useNormals_, result_};
}

void Ssao::execute(Context& ctx) {
    using namespace ssao;
    const BufferPtr in = ctx.get(image_);
    if (in->channelType("Z") != ChannelType::Float32) throw Error("the image needs a float32 depth channel 'Z'");
    const Camera camera = requireCamera(*in, "the image");
    if (camera.projection == Camera::Projection::Perspective
            ? !(camera.fovYDegrees > 0 && camera.fovYDegrees < 180)
            : !(camera.viewHeight > 0))
        throw Error("the image's camera has an invalid field of view or view height");
    const int w = in->width(), h = in->height();

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
    const Frame g = buildFrame(*in, camera, ctx.get(useNormals_), blurRadius, ctx);
    ctx.progress(0.1);
    // Raw AO into a padded plane (the blur reads past the borders); the
    // padding reads as unoccluded.
    auto raw = g.makePlane(1.0f);
    const bool hemisphere = ctx.get(method_) == Method::Hemisphere;
    ctx.parallelFor(0, h, 4, [&](int y0, int y1) {
        if (hemisphere)
            hemisphereAO(g, s, y0, y1, raw.get());
        else
            horizonAO(g, s, y0, y1, raw.get());
    });
    ctx.progress(0.8);
    if (blurRadius > 0) {
        const std::vector<float> spatial = blurWeights(blurRadius);
        auto tmp = g.makePlane(1.0f);
        ctx.parallelFor(0, h, 8, [&](int y0, int y1) { blurRows(g, s, spatial, false, y0, y1, raw.get(), tmp.get()); });
        ctx.parallelFor(0, h, 8, [&](int y0, int y1) { blurRows(g, s, spatial, true, y0, y1, tmp.get(), raw.get()); });
    }
    ctx.parallelFor(0, h, 64, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            const float* src = raw.get() + g.offset(0, y);
            const float* z = g.z.get() + g.offset(0, y);
            float* dst = ao + std::size_t(y) * std::size_t(w);
            for (int x = 0; x < w; ++x) {
                float a = std::clamp(1.0f - intensity * (1.0f - src[x]), 0.0f, 1.0f);
                if (power != 1.0f) a = std::pow(a, power);
                dst[x] = z[x] < std::numeric_limits<float>::infinity() && std::isfinite(a) ? a : 1.0f;
            }
        }
    });
    ctx.progress(1.0);
    ctx.set(result_, out);
}

}  // namespace darkroom
