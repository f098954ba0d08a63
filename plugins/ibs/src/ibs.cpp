#include "ibs.h"

#include "silhouette.h"

#include <darkroom/error.h>
#include <darkroom/view_geometry.h>

#include <algorithm>
#include <cmath>

namespace darkroom {

namespace {

// Headlight term L = ambient + (1 - ambient) max(0, N.V), V the unit vector
// from the surface to the eye, for every pixel with a surface; NaN elsewhere.
std::vector<float> headlight(Context& ctx, const Buffer& in, const Camera& camera, double ambient) {
    const int w = in.width(), h = in.height();
    const std::size_t n = in.pixelCount();
    const float* depth = in.hostFloat("Z");
    std::vector<float> nv[3] = {std::vector<float>(n), std::vector<float>(n), std::vector<float>(n)};
    float* view[3] = {nv[0].data(), nv[1].data(), nv[2].data()};
    const float* world[3] = {in.hostFloat("N.x"), in.hostFloat("N.y"), in.hostFloat("N.z")};
    if (world[0] && world[1] && world[2]) {
        worldToViewNormals(ctx, world, n, camera, view);  // captured normals are exact
    } else {
        NormalOutputs o;
        std::copy(view, view + 3, o.view);
        reconstructNormals(ctx, depth, w, h, camera, NormalMethod::Extrapolated, o);
    }
    const bool perspective = camera.projection == Camera::Projection::Perspective;
    std::vector<float> light(n);
    ctx.parallelFor(0, h, 16, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < w; ++x) {
                const std::size_t i = std::size_t(y) * w + x;
                // Unit vector to the eye in view space (z forward, so the eye is at -z).
                Vec3 v{0, 0, -1};
                if (perspective) {
                    double sx, sy;
                    camera.planeOffsets(x + 0.5, y + 0.5, sx, sy);
                    v = normalize(Vec3{-sx, -sy, -1});  // eye minus view position, unit
                }
                const double d = nv[0][i] * v.x + nv[1][i] * v.y + nv[2][i] * v.z;
                // NaN normals (no surface, or NaN in captured N) stay NaN and
                // are skipped by the caller.
                light[i] = float(ambient + (1.0 - ambient) * std::max(0.0, d));
                if (std::isnan(d)) light[i] = d;
            }
    });
    return light;
}

}  // namespace

void Ibs::execute(Context& ctx) {
    const BufferPtr in = ctx.get(image_);
    const float* depth = in->requireFloat("Z");
    const int w = in->width(), h = in->height();

    passes::SilhouetteOptions so;
    so.width = ctx.get(width_);
    so.depthThreshold = ctx.get(depthThreshold_);
    so.nearSide = ctx.get(side_) == Side::Near;
    if (!(so.width >= 0) || !(so.depthThreshold >= 0))
        throw Error("width and depthThreshold must be non-negative numbers");
    const std::uint32_t* ids = ctx.get(objectIds_) ? in->hostUInt("objectId") : nullptr;
    const double strength = std::clamp(ctx.get(strength_), 0.0, 1.0);
    const Color color = ctx.get(color_);
    const bool lighting = ctx.get(lighting_);
    const double luminance = ctx.get(luminance_);
    const double ambient = std::clamp(ctx.get(ambient_), 0.0, 1.0);

    const float* rgbIn[3] = {in->hostFloat("R"), in->hostFloat("G"), in->hostFloat("B")};
    const bool colour = rgbIn[0] && rgbIn[1] && rgbIn[2];
    const float* alphaIn = in->hostFloat("A");
    std::vector<ChannelDesc> fresh{"Silhouette"};
    if (colour) fresh.insert(fresh.end(), {"R", "G", "B"});
    if (colour && alphaIn) fresh.push_back("A");

    std::vector<float> light;
    if (colour && lighting) light = headlight(ctx, *in, requireCamera(*in, "input 'image' (for lighting)"), ambient);
    const std::vector<float> s = passes::silhouette(ctx, depth, ids, w, h, so);

    // Every fresh plane is written below.
    auto out = ctx.derive(in, fresh, Fill::None);
    std::copy(s.begin(), s.end(), out->writeFloat("Silhouette"));
    if (colour) {
        float* rgb[3] = {out->writeFloat("R"), out->writeFloat("G"), out->writeFloat("B")};
        float* alpha = alphaIn ? out->writeFloat("A") : nullptr;
        const float c[3] = {color.r, color.g, color.b};
        ctx.parallelFor(0, h, 16, [&](int y0, int y1) {
            for (std::size_t i = std::size_t(y0) * w; i < std::size_t(y1) * w; ++i) {
                double v[3] = {rgbIn[0][i], rgbIn[1][i], rgbIn[2][i]};
                // Lighting touches surfaces only; background keeps its colour.
                if (!light.empty() && !std::isnan(light[i]))
                    for (double& x : v) x *= luminance * light[i];
                // Straight-alpha "over" of the outline colour with opacity k.
                const double k = strength * double(color.a) * s[i];
                const double a = alphaIn ? alphaIn[i] : 1.0;
                const double ao = k + a * (1.0 - k);
                for (int ch = 0; ch < 3; ++ch)
                    rgb[ch][i] = ao > 0 ? float((c[ch] * k + v[ch] * a * (1.0 - k)) / ao) : float(v[ch]);
                if (alpha) alpha[i] = float(ao);
            }
        });
    }
    ctx.progress(1.0);
    ctx.set(result_, out);
}

}  // namespace darkroom
