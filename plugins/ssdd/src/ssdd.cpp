#include "ssdd.h"

#include "../../normals/lib/pass_through.h"
#include "masked_blur.h"

#include <darkroom/error.h>

#include <algorithm>
#include <cmath>

namespace darkroom {

PortList Ssdd::ports() const {
    PortList p;
    p.imageIn("image", "Depth Z (planar view depth, +inf background) with its camera in the metadata",
              {"Z"});
    p.floatIn("strength", 0.5, 0.0, 100.0,
              "Darkening per unit of depth difference, measured in the world size of sigma at the "
              "pixel's depth: factor = exp(-strength * max(0, -dD) / sigmaWorld)");
    p.floatIn("sigma", 0.01, 0.0, 512.0,
              "Standard deviation of the Gaussian, in pixels or as a fraction of the image height");
    p.enumIn("sigmaUnits", {"imageHeight", "pixels"}, "imageHeight",
             "imageHeight: sigma is a fraction of the image height (same look at any resolution); "
             "pixels: sigma in pixels");
    p.boolIn("apply", false, "Also multiply R, G, B (when present) by the factor; otherwise only add SSDD");
    p.imageOut("image",
               "All input channels plus SSDD, a darkening factor in [0, 1] (1 = unchanged; 1 on "
               "background and where Z is not finite)",
               {"SSDD"});
    return p;
}

void Ssdd::execute(Context& ctx) {
    const BufferPtr in = ctx.requireImage("image");
    const std::string node = "SSDD '" + ctx.nodeName() + "'";
    const float* depth = in->requireFloat("Z");
    const Camera camera = passes::requireCamera(*in, node + ": input 'image'");
    const int w = in->width(), h = in->height();
    const double strength = ctx.getFloat("strength");
    double sigma = ctx.getFloat("sigma");
    const std::string& units = ctx.getString("sigmaUnits");
    if (units == "imageHeight") sigma *= h;
    else if (units != "pixels")
        throw Error(node + ": sigmaUnits must be 'imageHeight' or 'pixels', got '" + units + "'");
    if (!(sigma >= 0.0) || !std::isfinite(sigma) || !(strength >= 0.0) || !std::isfinite(strength))
        throw Error(node + ": sigma and strength must be finite and non-negative");

    const bool apply = ctx.getBool("apply") && in->hostFloat("R") && in->hostFloat("G") && in->hostFloat("B");
    std::vector<std::string> added{"SSDD"};
    if (apply) added.insert(added.end(), {"R", "G", "B"});
    auto out = passes::allocatePassThrough(ctx, *in, added);
    float* factor = out->requireFloat("SSDD");
    const std::size_t n = in->pixelCount();

    // Below a tenth of a pixel the blur is the identity: dD = 0.
    const bool active = sigma >= 0.1 && strength > 0.0 && n > 0;
    std::vector<float> blurred;
    if (active) blurred = passes::maskedGaussianDepth(ctx, depth, w, h, sigma);
    if (ctx.cancelled()) return;
    const double footprint = sigma * camera.pixelSizeAt(1.0);  // world size of sigma at unit depth
    const bool perspective = camera.projection == Camera::Projection::Perspective;
    ctx.parallelFor(0, h, 16, [&](int y0, int y1) {
        for (std::size_t i = std::size_t(y0) * w; i < std::size_t(y1) * w; ++i) {
            float f = 1.0f;
            if (active && passes::isSurface(depth[i])) {
                const double dd = double(blurred[i]) - double(depth[i]);
                // Scale-free: a depth step is compared with how wide the blur
                // is in the world at this depth.
                const double s = perspective ? footprint * std::abs(double(depth[i])) : footprint;
                if (dd < 0.0 && s > 0.0) f = float(std::exp(-strength * (-dd) / s));
                if (!(f >= 0.0f)) f = 0.0f;
            }
            factor[i] = f;
        }
    });
    if (apply) {
        for (const char* c : {"R", "G", "B"}) {
            const float* s = in->hostFloat(c);
            float* d = out->hostFloat(c);
            ctx.parallelFor(0, h, 16, [&](int y0, int y1) {
                for (std::size_t i = std::size_t(y0) * w; i < std::size_t(y1) * w; ++i) d[i] = s[i] * factor[i];
            });
        }
    }
    if (ctx.cancelled()) return;
    ctx.progress(1.0);
    ctx.setOutput("image", BufferPtr(std::move(out)));
}

}  // namespace darkroom
