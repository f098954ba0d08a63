#include "ssdd.h"

#include "darkening.h"

#include <darkroom/error.h>
#include <darkroom/view_geometry.h>

#include <algorithm>
#include <cmath>

namespace darkroom {

void Ssdd::execute(Context& ctx) {
    const BufferPtr in = ctx.get(image_);
    const float* depth = requireDepth(*in);
    const Camera camera = camera_.get(ctx, *in, depth);
    const int w = in->width(), h = in->height();
    const double strength = ctx.get(strength_);
    double sigma = ctx.get(sigma_);
    if (ctx.get(sigmaUnits_) == SigmaUnits::ImageHeight) sigma *= h;
    if (!(sigma >= 0.0) || !std::isfinite(sigma) || !(strength >= 0.0) || !std::isfinite(strength))
        throw Error("sigma and strength must be finite and non-negative");

    const bool apply = ctx.get(apply_) && in->hostFloat("R") && in->hostFloat("G") && in->hostFloat("B");
    std::vector<ChannelDesc> fresh{"SSDD"};
    if (apply) fresh.insert(fresh.end(), {"R", "G", "B"});
    // Every fresh plane is written below.
    auto out = ctx.derive(in, fresh, Fill::None);
    float* factor = out->writeFloat("SSDD");
    const std::size_t n = in->pixelCount();

    // Below a tenth of a pixel the blur is the identity: dD = 0.
    const bool active = sigma >= 0.1 && strength > 0.0 && n > 0;
    if (active) {
        passes::DarkeningJob job;
        job.depth = depth;
        job.width = w;
        job.height = h;
        job.horizontal = job.vertical = passes::boxCascade(sigma, std::max(w, h));
        job.strength = strength;
        job.footprint = sigma * camera.pixelSizeAt(1.0);  // world size of sigma at unit depth
        job.perspective = camera.projection == Camera::Projection::Perspective;
        job.factor = factor;
        passes::depthDarkening(ctx, job);
    } else {
        std::fill_n(factor, n, 1.0f);
    }
    if (apply) {
        for (const char* c : {"R", "G", "B"}) {
            const float* s = in->hostFloat(c);
            float* d = out->writeFloat(c);
            ctx.parallelFor(0, h, 16, [&](int y0, int y1) {
                for (std::size_t i = std::size_t(y0) * w; i < std::size_t(y1) * w; ++i) d[i] = s[i] * factor[i];
            });
        }
    }
    ctx.progress(1.0);
    ctx.set(result_, out);
}

}  // namespace darkroom
