#include "ssdof.h"

#include "coc.h"
#include "gathers.h"

#include <darkroom/error.h>
#include <darkroom/view_geometry.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace darkroom {

using namespace ssdof;

void SSDoF::execute(Context& ctx) {
    const BufferPtr in = ctx.get(image_);
    const int width = in->width(), height = in->height();
    const float* R = in->requireFloat("R");
    const float* G = in->requireFloat("G");
    const float* B = in->requireFloat("B");
    const float* A = in->hostFloat("A");
    const float* Z = in->requireFloat("Z");
    const Camera camera = requireCamera(*in, "the image (the circle of confusion needs its field of view)");

    const double aperture = ctx.get(aperture_);
    double focal = ctx.get(focalDistance_);
    if (!(focal > 0.0)) focal = autoFocusDistance(Z, width, height);
    const LensModel lens = makeLens(camera, height, aperture, focal, ctx.get(maxBlur_));

    WorkImage w;
    w.width = width;
    w.height = height;
    w.colour.resize(in->pixelCount());
    w.coc.resize(in->pixelCount());
    bool anyBlur = false;
    for (std::size_t i = 0; i < in->pixelCount(); ++i) {
        w.coc[i] = lens.signedRadius(Z[i]);
        anyBlur = anyBlur || std::fabs(w.coc[i]) >= kInFocus;
        // Premultiplied; a non-finite component (NaN colour on background) carries no light.
        const float a = A ? (std::isfinite(A[i]) ? A[i] : 0.0f) : 1.0f;
        auto pm = [&](float c) { return std::isfinite(c) ? c * a : 0.0f; };
        w.colour[i] = {pm(R[i]), pm(G[i]), pm(B[i]), a};
    }

    if (!anyBlur) {  // nothing out of focus: the input is the answer
        ctx.progress(1.0);
        ctx.set(result_, in);
        return;
    }
    computeNearReach(w);

    GatherResult g;
    if (ctx.get(method_) == Method::Hexagon)
        gatherHexagon(w, ctx.get(rotation_), ctx, g);
    else
        gatherDisc(w, int(ctx.get(samples_)), ctx, g);

    // New colour, every pixel written below; the rest is shared.
    std::vector<ChannelDesc> fresh{"R", "G", "B"};
    if (A) fresh.push_back("A");
    auto out = ctx.derive(in, fresh, Fill::None);
    float* oR = out->writeFloat("R");
    float* oG = out->writeFloat("G");
    float* oB = out->writeFloat("B");
    float* oA = A ? out->writeFloat("A") : nullptr;
    ctx.parallelFor(0, height, 16, [&](int y0, int y1) {
        for (std::size_t i = std::size_t(y0) * width; i < std::size_t(y1) * width; ++i) {
            if (g.unchanged[i]) {  // in focus, nothing bleeds in: bit-identical
                oR[i] = R[i];
                oG[i] = G[i];
                oB[i] = B[i];
                if (oA) oA[i] = A[i];
                continue;
            }
            const Rgba& c = g.colour[i];
            // Straight alpha out; a fully transparent result is transparent black.
            const float inv = c.a > 0.0f ? 1.0f / c.a : 0.0f;
            oR[i] = A ? c.r * inv : c.r;
            oG[i] = A ? c.g * inv : c.g;
            oB[i] = A ? c.b * inv : c.b;
            if (oA) oA[i] = std::min(c.a, 1.0f);
        }
    });
    ctx.progress(1.0);
    ctx.set(result_, out);
}

}  // namespace darkroom
