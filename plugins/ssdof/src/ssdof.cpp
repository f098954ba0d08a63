#include "ssdof.h"

#include "coc.h"
#include "gathers.h"

#include <darkroom/error.h>
#include <darkroom/view_geometry.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

namespace darkroom {

using namespace ssdof;

void Ssdof::execute(Context& ctx) {
    const BufferPtr in = ctx.get(image_);
    const int width = in->width(), height = in->height();
    const float* R = in->requireFloat("R");
    const float* G = in->requireFloat("G");
    const float* B = in->requireFloat("B");
    const float* A = in->hostFloat("A");
    const float* Z = requireDepth(*in);
    const Camera camera = camera_.get(ctx, *in, Z);

    const double aperture = ctx.get(aperture_);
    double focal = ctx.get(focalDistance_);
    if (!(focal > 0.0)) focal = autoFocusDistance(Z, width, height);
    const LensModel lens = makeLens(camera, height, aperture, focal, ctx.get(maxBlur_));

    const float* rgba[4] = {R, G, B, A};
    WorkImage w;
    if (!buildWorkImage(ctx, rgba, Z, width, height, lens, w)) {  // nothing out of focus: the input is the answer
        ctx.progress(1.0);
        ctx.set(result_, in);
        return;
    }
    computeNearReach(w);
    if (double(w.stride) * double(height + 2 * w.pad) >= double(std::numeric_limits<std::int32_t>::max()))
        throw Error("the image (" + std::to_string(width) + "x" + std::to_string(height) +
                    ") is too large for Ssdof's 32-bit sample indices");

    // New colour, every pixel written by the gather; the rest is shared.
    std::vector<ChannelDesc> fresh{"R", "G", "B"};
    if (A) fresh.push_back("A");
    auto out = ctx.derive(in, fresh, Fill::None);
    const Output o{{R, G, B, A},
                   {out->writeFloat("R"), out->writeFloat("G"), out->writeFloat("B"), A ? out->writeFloat("A") : nullptr}};
    if (ctx.get(method_) == Method::Hexagon)
        gatherHexagon(w, ctx.get(rotation_), ctx, o);
    else
        gatherDisc(w, int(ctx.get(samples_)), ctx, o);
    if (ctx.cancelled()) throw Cancelled();
    ctx.progress(1.0);
    ctx.set(result_, out);
}

}  // namespace darkroom
