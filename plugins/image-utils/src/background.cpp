#include "background.h"

#include "image_checks.h"

#include <darkroom/error.h>

#include <algorithm>
#include <cmath>

namespace darkroom {

PortList Background::ports() const {
    PortList p;
    p.imageIn("image",
              "Linear R, G, B with straight alpha A; without A, finite depth Z counts as opaque and +inf as "
              "empty",
              {"R", "G", "B"});
    p.enumIn("mode", {"color", "gradient"}, "gradient", "color: one colour; gradient: 'top' at the first row to "
             "'bottom' at the last, linear in between");
    p.colorIn("color", Color{0.32f, 0.34f, 0.43f, 1.0f}, "Background colour (mode color)");
    p.colorIn("top", Color{0.0f, 0.0f, 0.16f, 1.0f}, "Colour of the top row (mode gradient)");
    p.colorIn("bottom", Color{0.32f, 0.34f, 0.43f, 1.0f}, "Colour of the bottom row (mode gradient)");
    p.imageOut("image",
               "The image over the background: R, G, B and A (1 where the background is opaque); other channels, "
               "Z included, pass through",
               {"R", "G", "B", "A"});
    return p;
}

void Background::execute(Context& ctx) {
    const std::string node = "Background '" + ctx.nodeName() + "'";
    const BufferPtr in = ctx.requireImage("image");
    const float* c[3];
    const char* names[3] = {"R", "G", "B"};
    for (int k = 0; k < 3; ++k) c[k] = utils::requireFloatChannel(*in, names[k], node, "image");
    const float* alpha = in->hostFloat("A");
    const float* depth = in->hostFloat("Z");
    if (!alpha && !depth)
        throw Error(node + ": the image has neither alpha A nor depth Z to tell scene from background; it has " +
                    utils::channelList(*in));
    const bool gradient = ctx.getString("mode") == "gradient";
    const Color top = gradient ? ctx.getColor("top") : ctx.getColor("color");
    const Color bottom = gradient ? ctx.getColor("bottom") : top;

    std::vector<ChannelDesc> channels = in->channels();
    if (!alpha) channels.push_back({"A"});
    auto out = ctx.allocate(in->width(), in->height(), channels);
    out->metadata() = in->metadata();
    for (const auto& ch : in->channels())
        if (ch.name != "R" && ch.name != "G" && ch.name != "B" && ch.name != "A") utils::copyChannel(*in, *out, ch);
    float* o[3] = {out->hostFloat("R"), out->hostFloat("G"), out->hostFloat("B")};
    float* oa = out->hostFloat("A");
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
    if (ctx.cancelled()) return;
    ctx.progress(1.0);
    ctx.setOutput("image", BufferPtr(std::move(out)));
}

}  // namespace darkroom
