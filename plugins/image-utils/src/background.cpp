#include "background.h"

#include "image_checks.h"

#include <darkroom/error.h>

#include <algorithm>
#include <cmath>
#include <darkroom/channel_text.h>

namespace darkroom {

void Background::execute(Context& ctx) {
    const BufferPtr in = ctx.get(image_);
    const float* c[3];
    const char* names[3] = {"R", "G", "B"};
    for (int k = 0; k < 3; ++k) c[k] = utils::requireFloatChannel(*in, names[k], "image");
    const float* alpha = in->hostFloat("A");
    const float* depth = in->hostFloat("Z");
    if (!alpha && !depth)
        throw Error("the image has neither alpha A nor depth Z to tell scene from background; it has " +
                    channelListText(*in));
    const bool gradient = ctx.get(mode_) == Mode::Gradient;
    const Color top = gradient ? ctx.get(top_) : ctx.get(color_);
    const Color bottom = gradient ? ctx.get(bottom_) : top;

    // New colour and alpha, every pixel written; the rest is shared.
    auto out = ctx.derive(in, {"R", "G", "B", "A"}, Fill::None);
    float* o[3] = {out->writeFloat("R"), out->writeFloat("G"), out->writeFloat("B")};
    float* oa = out->writeFloat("A");
    const int w = in->width(), h = in->height();

    ctx.parallelFor(0, h, 8, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            // (1 - t) * top + t * bottom is exactly top at t = 0 and bottom at t = 1.
            const float t = h > 1 ? float(y) / float(h - 1) : 0.5f;
            const float s = 1.0f - t;
            const float bg[4] = {s * top.r + t * bottom.r, s * top.g + t * bottom.g, s * top.b + t * bottom.b,
                                 s * top.a + t * bottom.a};
            for (int x = 0; x < w; ++x) {
                const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
                float a = alpha ? alpha[i] : (std::isfinite(depth[i]) ? 1.0f : 0.0f);
                a = std::isfinite(a) ? std::clamp(a, 0.0f, 1.0f) : 0.0f;  // NaN alpha: nothing there
                if (a >= 1.0f) {
                    for (int k = 0; k < 3; ++k) o[k][i] = c[k][i];
                    oa[i] = 1.0f;
                } else if (a <= 0.0f) {
                    // Colour under zero alpha is ignored, so NaN there cannot leak.
                    for (int k = 0; k < 3; ++k) o[k][i] = bg[k];
                    oa[i] = bg[3];
                } else {
                    // Straight alpha "over": premultiply, add, divide by the new alpha.
                    const float under = bg[3] * (1.0f - a);
                    const float outA = a + under;
                    for (int k = 0; k < 3; ++k) o[k][i] = (c[k][i] * a + bg[k] * under) / outA;
                    oa[i] = outA;
                }
            }
        }
    });
    ctx.progress(1.0);
    ctx.set(result_, out);
}

}  // namespace darkroom
