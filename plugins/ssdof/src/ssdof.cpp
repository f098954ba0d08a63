#include "ssdof.h"

#include "coc.h"
#include "gathers.h"

#include <darkroom/error.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace darkroom {

using namespace ssdof;

PortList SSDoF::ports() const {
    PortList p;
    p.imageIn("image",
              "Linear R, G, B (A optional, straight alpha) and planar depth Z (+inf = background); "
              "the camera in the metadata gives the field of view",
              {"R", "G", "B", "Z"});
    const double big = 1e30;
    p.floatIn("focalDistance", 0.0, 0.0, big,
              "Planar depth in focus, world units; 0 = auto-focus on the median depth of the 5x5 "
              "centre pixels (infinity when they are all background)");
    p.floatIn("aperture", 0.05, 0.0, big,
              "Lens diameter in world units (a real lens: focal length / f-number); 0 = pinhole, "
              "everything sharp");
    p.floatIn("maxBlur", 16.0, 0.0, 128.0, "Largest circle-of-confusion radius, pixels");
    p.enumIn("method", {"disc", "hexagon"}, "disc",
             "disc: round aperture, golden-angle spiral gather with `samples` taps; hexagon: "
             "hexagonal aperture as separable skewed box blurs (McIntosh et al. 2012), taps follow "
             "the CoC");
    p.intIn("samples", 32, 4, 1024, "Taps of the disc gather per layer (disc method)");
    p.floatIn("rotation", 0.0, 0.0, 60.0,
              "Hexagon orientation: a corner points this many degrees clockwise from up (hexagon "
              "method)");
    p.imageOut("image",
               "Input channels passed through with R, G, B (and A if present) blurred; in-focus "
               "pixels without near-field bleeding are bit-identical",
               {"R", "G", "B"});
    return p;
}

void SSDoF::execute(Context& ctx) {
    const BufferPtr in = ctx.requireImage("image");
    const std::string node = "SSDoF '" + ctx.nodeName() + "'";
    const int width = in->width(), height = in->height();
    const float* R = in->requireFloat("R");
    const float* G = in->requireFloat("G");
    const float* B = in->requireFloat("B");
    const float* A = in->hostFloat("A");
    const float* Z = in->requireFloat("Z");
    if (!in->metadata().camera)
        throw Error(node + ": the image carries no camera; the circle of confusion needs its field of view");

    const double aperture = ctx.getFloat("aperture");
    double focal = ctx.getFloat("focalDistance");
    if (!(focal > 0.0)) focal = autoFocusDistance(Z, width, height);
    const LensModel lens = makeLens(*in->metadata().camera, height, aperture, focal, ctx.getFloat("maxBlur"));

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

    auto out = ctx.allocate(width, height, in->channels());
    out->metadata() = in->metadata();
    for (const auto& c : in->channels()) {
        if (c.type == ChannelType::UInt32)
            std::copy_n(in->hostUInt(c.name), in->pixelCount(), out->hostUInt(c.name));
        else
            std::copy_n(in->hostFloat(c.name), in->pixelCount(), out->hostFloat(c.name));
    }
    if (!anyBlur) {  // nothing out of focus: the copy is the answer
        ctx.progress(1.0);
        ctx.setOutput("image", BufferPtr(std::move(out)));
        return;
    }
    computeNearReach(w);

    GatherResult g;
    if (ctx.getString("method") == "hexagon")
        gatherHexagon(w, ctx.getFloat("rotation"), ctx, g);
    else
        gatherDisc(w, int(ctx.getInt("samples")), ctx, g);
    if (ctx.cancelled()) return;

    float* oR = out->hostFloat("R");
    float* oG = out->hostFloat("G");
    float* oB = out->hostFloat("B");
    float* oA = A ? out->hostFloat("A") : nullptr;
    ctx.parallelFor(0, height, 16, [&](int y0, int y1) {
        for (std::size_t i = std::size_t(y0) * width; i < std::size_t(y1) * width; ++i) {
            if (g.unchanged[i]) continue;  // already copied
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
    ctx.setOutput("image", BufferPtr(std::move(out)));
}

}  // namespace darkroom
