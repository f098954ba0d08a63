#include "ssao.h"

#include "ao_estimators.h"
#include "bilateral_blur.h"
#include "pixel_geometry.h"

#include <darkroom/error.h>

#include <algorithm>
#include <cmath>

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

    const PixelGeometry g = buildPixelGeometry(*in, camera, ctx.get(useNormals_), ctx);
    ctx.progress(0.1);
    if (ctx.get(method_) == Method::Hemisphere)
        hemisphereAO(g, s, ctx, ao);
    else
        horizonAO(g, s, ctx, ao);
    ctx.progress(0.8);
    bilateralBlur(g, s, int(ctx.get(blurRadius_)), ctx, ao);
    ctx.parallelFor(0, h, 64, [&](int y0, int y1) {
        for (std::size_t i = std::size_t(y0) * std::size_t(w); i < std::size_t(y1) * std::size_t(w); ++i) {
            float a = std::clamp(1.0f - intensity * (1.0f - ao[i]), 0.0f, 1.0f);
            if (power != 1.0f) a = std::pow(a, power);
            ao[i] = g.valid[i] && std::isfinite(a) ? a : 1.0f;
        }
    });
    ctx.progress(1.0);
    ctx.set(result_, out);
}

}  // namespace darkroom
