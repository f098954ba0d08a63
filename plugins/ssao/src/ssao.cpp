#include "ssao.h"

#include "ao_estimators.h"
#include "bilateral_blur.h"
#include "view_geometry.h"

#include <darkroom/error.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace darkroom {

PortList Ssao::ports() const {
    PortList p;
    p.imageIn("image", "G-buffer with planar depth Z (+inf = background) and a camera in its metadata",
              {"Z"});
    p.enumIn("method", {"hemisphere", "horizon"}, "horizon",
             "hemisphere: classic normal-oriented point sampling with a range check; horizon: "
             "GTAO-style slices with an analytic cosine-weighted inner integral (comparable to "
             "ray-traced AO of the same radius)");
    p.enumIn("geometry", {"surface", "points"}, "surface",
             "surface: the depth buffer is a height field (solid behind every pixel); points: "
             "particles and thin lines, only nearer occluders within `thickness` count");
    p.floatIn("radius", 0.05, 1e-6, 1e9, "Occlusion radius, in radiusUnits");
    p.enumIn("radiusUnits", {"world", "imageHeight"}, "imageHeight",
             "world: world units; imageHeight: a fraction of the image height, converted to world "
             "units at each pixel's depth");
    p.intIn("samples", 16, 1, 1024, "hemisphere: sample points per pixel");
    p.intIn("slices", 4, 1, 64, "horizon: slice planes per pixel");
    p.intIn("steps", 8, 1, 256, "horizon: depth samples per side of each slice");
    p.floatIn("falloff", 0.2, 0.0, 1.0,
              "Fraction of the radius over which an occluder's weight fades to 0 at the radius; 0 = "
              "hard cut as in ray-traced AO");
    p.floatIn("bias", 0.01, 0.0, 0.5,
              "The receiver is lifted along its normal by bias x radius, against self-occlusion "
              "from depth quantisation and curvature");
    p.floatIn("thickness", 0.5, 0.0, 1e6,
              "points geometry: assumed occluder thickness along the view, in units of the radius");
    p.floatIn("intensity", 1.0, 0.0, 10.0, "Scales occlusion: AO = 1 - intensity (1 - AO), then clamped");
    p.floatIn("power", 1.0, 0.1, 10.0, "Exponent applied to AO after intensity");
    p.intIn("seed", 0, 0, 2147483647, "Seed of the per-pixel noise (hash of pixel and seed)");
    p.intIn("blurRadius", 2, 0, 32, "Half-width in pixels of the depth-aware blur; 0 disables it");
    p.boolIn("useNormals", false,
             "Use the input's world-space normals N.x/N.y/N.z when present instead of "
             "reconstructing them from Z");
    p.imageOut("image", "The input channels plus AO in [0, 1] (1 = unoccluded; 1 on background)", {"AO"});
    return p;
}

void Ssao::execute(Context& ctx) {
    using namespace ssao;
    const BufferPtr in = ctx.requireImage("image");
    const std::string node = "SSAO '" + ctx.nodeName() + "'";
    if (in->channelType("Z") != ChannelType::Float32)
        throw Error(node + ": the image needs a float32 depth channel 'Z'");
    if (!in->metadata().camera)
        throw Error(node + ": the image carries no camera; SSAO needs it to reconstruct positions from Z");
    const Camera& camera = *in->metadata().camera;
    if (camera.projection == Camera::Projection::Perspective
            ? !(camera.fovYDegrees > 0 && camera.fovYDegrees < 180)
            : !(camera.viewHeight > 0))
        throw Error(node + ": the image's camera has an invalid field of view or view height");
    const int w = in->width(), h = in->height();

    AoSettings s;
    s.radius = float(ctx.getFloat("radius"));
    s.radiusInImageHeight = ctx.getString("radiusUnits") == "imageHeight";
    s.samples = int(ctx.getInt("samples"));
    s.slices = int(ctx.getInt("slices"));
    s.steps = int(ctx.getInt("steps"));
    s.falloff = float(ctx.getFloat("falloff"));
    s.bias = float(ctx.getFloat("bias"));
    s.seed = std::uint32_t(ctx.getInt("seed"));
    s.geometry = ctx.getString("geometry") == "points" ? Geometry::Points : Geometry::Surface;
    const float intensity = float(ctx.getFloat("intensity"));
    const float power = float(ctx.getFloat("power"));
    if (!(s.radius > 0) || !std::isfinite(s.radius)) throw Error(node + ": radius must be positive and finite");

    std::vector<ChannelDesc> channels = in->channels();
    if (!in->hasChannel("AO")) channels.push_back({"AO", ChannelType::Float32});
    auto out = ctx.allocate(w, h, channels);
    out->metadata() = in->metadata();
    const std::size_t n = in->pixelCount();
    float* ao = out->requireFloat("AO");
    for (const auto& c : in->channels()) {
        if (c.name == "AO") continue;
        if (c.type == ChannelType::UInt32)
            std::memcpy(out->hostUInt(c.name), in->hostUInt(c.name), n * sizeof(std::uint32_t));
        else
            std::memcpy(out->hostFloat(c.name), in->hostFloat(c.name), n * sizeof(float));
    }
    if (n == 0) {
        ctx.setOutput("image", BufferPtr(std::move(out)));
        return;
    }

    const ViewGeometry g = buildViewGeometry(*in, camera, ctx.getBool("useNormals"), ctx);
    s.thickness = float(ctx.getFloat("thickness"));
    if (ctx.cancelled()) return;
    ctx.progress(0.1);
    if (ctx.getString("method") == "hemisphere")
        hemisphereAO(g, s, ctx, ao);
    else
        horizonAO(g, s, ctx, ao);
    if (ctx.cancelled()) return;
    ctx.progress(0.8);
    bilateralBlur(g, s, int(ctx.getInt("blurRadius")), ctx, ao);
    if (ctx.cancelled()) return;
    ctx.parallelFor(0, h, 64, [&](int y0, int y1) {
        for (std::size_t i = std::size_t(y0) * std::size_t(w); i < std::size_t(y1) * std::size_t(w); ++i) {
            float a = std::clamp(1.0f - intensity * (1.0f - ao[i]), 0.0f, 1.0f);
            if (power != 1.0f) a = std::pow(a, power);
            ao[i] = g.valid[i] && std::isfinite(a) ? a : 1.0f;
        }
    });
    ctx.progress(1.0);
    ctx.setOutput("image", BufferPtr(std::move(out)));
}

}  // namespace darkroom
