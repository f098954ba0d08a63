#include "point_list_ao.h"

#include "list_occlusion.h"
#include "list_primitives.h"

#include <darkroom/depth_input.h>
#include <darkroom/error.h>
#include <darkroom/data/cinema/row.h>
#include <darkroom/scene/point_list.h>
#include <darkroom/view_geometry.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace darkroom {

namespace {



// World-space normal planes: the input's N.x/N.y/N.z, or reconstructed from
// depth (receivers on the list's own primitives get theirs from the list).
struct Normals {
    std::vector<float> planes[3];
    const float* at[3] = {nullptr, nullptr, nullptr};
    bool captured = false;
};

Normals receiverNormals(Context& ctx, const Buffer& in, const Camera& camera, const float* z) {
    Normals n;
    const char* names[3] = {"N.x", "N.y", "N.z"};
    n.captured = in.hasChannel(names[0]) && in.hasChannel(names[1]) && in.hasChannel(names[2]);
    if (n.captured) {
        for (int k = 0; k < 3; ++k) n.at[k] = in.requireFloat(names[k]);
        return n;
    }
    NormalOutputs out;
    for (int k = 0; k < 3; ++k) {
        n.planes[k].resize(in.pixelCount());
        out.world[k] = n.planes[k].data();
        n.at[k] = n.planes[k].data();
    }
    reconstructNormals(ctx, z, in.width(), in.height(), camera, NormalMethod::Extrapolated, out);
    return n;
}

}  // namespace

void PointListAo::execute(Context& ctx) {
    const BufferPtr in = ctx.get(image_);
    const float* z = requireDepth(*in);
    const Camera camera = requireCamera(*in, "input 'image'");

    const PointList list =
        readNodePointList(ctx, ctx.getString(points_.name()), [&]() -> const Row& { return ctx.get(row_); });

    const ViewGeometry view(camera, in->width(), in->height());
    const bool perImageHeight = ctx.get(radiusUnits_) == RadiusUnits::ImageHeight;
    const float radius = float(ctx.get(radius_));
    // World radius at depth zp: a fraction of the image height there.
    auto radiusAt = [&](float zp) { return perImageHeight ? radius * view.pixelSizeAt(zp) * float(in->height()) : radius; };
    // Cells half the radius wide, at the list's median depth when the
    // radius follows depth.
    const listao::Primitives prims = listao::listPrimitives(list, camera, ctx.get(pointRadius_), ctx.get(radiusScale_));
    std::vector<float> depths;
    for (const V3f& c : prims.centres) depths.push_back(c.z);
    for (const V3f& a : prims.segA) depths.push_back(a.z);
    float typicalDepth = 1.0f;
    if (!depths.empty()) {
        std::nth_element(depths.begin(), depths.begin() + std::ptrdiff_t(depths.size() / 2), depths.end());
        typicalDepth = std::max(1e-6f, depths[depths.size() / 2]);
    }
    const listao::PrimitiveGrid grid(prims, 0.5f * radiusAt(typicalDepth));
    const listao::ListOcclusion occlusion(grid);
    ctx.progress(0.1);

    const Normals normals = receiverNormals(ctx, *in, camera, z);
    const bool multiply = ctx.get(existing_) == ExistingAo::Multiply && in->hasChannel("AO");
    const float* before = multiply ? in->requireFloat("AO") : nullptr;
    const float intensity = float(ctx.get(intensity_)), power = float(ctx.get(power_));
    auto out = ctx.derive(in, {"AO"}, Fill::None);
    float* ao = out->writeFloat("AO");
    const int w = in->width(), h = in->height();
    auto shadeRow = [&](int y) {
        for (int x = 0; x < w; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
            float a = 1.0f;
            if (isSurface(z[i]) && z[i] > 0) {
                const V3f p = view.position(x, y, z[i]);
                V3f n = normalize(view.toView(Vec3{normals.at[0][i], normals.at[1][i], normals.at[2][i]}));
                if (!normals.captured) occlusion.surfaceNormal(p, 1e-3f * view.pixelSizeAt(z[i]) + 1e-5f * z[i], n);
                if (dot(n, view.toCamera(p)) < 0) n = n * -1.0f;
                if (std::isfinite(n.x + n.y + n.z)) a = occlusion.visibility(p, n, radiusAt(z[i]));
                a = std::pow(std::clamp(1.0f - intensity * (1.0f - a), 0.0f, 1.0f), power);
            }
            ao[i] = before ? a * before[i] : a;
        }
    };
    // Bands of rows between progress reports and cancellation checks: a
    // dense list takes seconds.
    constexpr int kBand = 32;
    for (int b0 = 0; b0 < h; b0 += kBand) {
        const int b1 = std::min(h, b0 + kBand);
        ctx.parallelFor(b0, b1, 1, [&](int y0, int y1) {
            for (int y = y0; y < y1; ++y) shadeRow(y);
        });
        if (ctx.cancelled()) throw Cancelled();
        ctx.progress(0.1 + 0.9 * double(b1) / h);
    }
    ctx.set(result_, out);
}

}  // namespace darkroom
