#include "mix.h"

#include "image_checks.h"

#include <darkroom/error.h>

#include <cmath>

namespace darkroom {

namespace {

struct Rgba {
    const float* c[3] = {nullptr, nullptr, nullptr};
    const float* a = nullptr;  // nullptr: opaque
};

Rgba colourOf(const Buffer& b, const std::string& node, const std::string& port) {
    Rgba r;
    const char* names[3] = {"R", "G", "B"};
    for (int k = 0; k < 3; ++k) r.c[k] = utils::requireFloatChannel(b, names[k], node, port);
    r.a = b.hostFloat("A");
    return r;
}

bool finiteColour(const Rgba& c, std::size_t i) {
    return std::isfinite(c.c[0][i]) && std::isfinite(c.c[1][i]) && std::isfinite(c.c[2][i]) &&
           (!c.a || std::isfinite(c.a[i]));
}

}  // namespace

PortList Mix::ports() const {
    PortList p;
    p.imageIn("image", "Base colour: linear R, G, B and optionally straight alpha A; every channel passes through",
              {"R", "G", "B"});
    p.optionalImageIn("other",
                      "multiply: the image holding factorChannel (unconnected: taken from 'image'); blend, over, "
                      "add: the second colour R, G, B (and A); same size as 'image'");
    p.enumIn("mode", {"multiply", "blend", "over", "add"}, "multiply",
             "multiply: RGB *= mix(1, factor, amount); blend: mix(image, other, amount) on R, G, B, A; over: "
             "'other' composited over 'image' with other's alpha times amount; add: RGB += amount * other");
    p.stringIn("factorChannel", "AO", "multiply: the float channel holding the factor, e.g. AO (SSAO) or SSDD");
    p.floatIn("amount", 1.0, 0.0, 1.0, "Strength: 0 leaves 'image' unchanged, 1 applies fully");
    p.imageOut("image", "'image' with new R, G, B (and A for blend and over); all other channels passed through");
    return p;
}

void Mix::execute(Context& ctx) {
    const std::string node = "Mix '" + ctx.nodeName() + "'";
    const BufferPtr in = ctx.requireImage("image");
    const BufferPtr other = ctx.image("other");
    const std::string& mode = ctx.getString("mode");
    const float amount = float(ctx.getFloat("amount"));
    if (other) utils::requireSameSize(*in, *other, node, "image", "other");
    const Rgba base = colourOf(*in, node, "image");
    const float* depth = in->hostFloat("Z");

    const float* factor = nullptr;
    Rgba second;
    if (mode == "multiply") {
        const std::string& name = ctx.getString("factorChannel");
        factor = utils::requireFloatChannel(other ? *other : *in, name, node, other ? "other" : "image");
    } else {
        if (!other) throw Error(node + ": mode '" + mode + "' needs an image on 'other'");
        second = colourOf(*other, node, "other");
    }

    auto out = ctx.allocate(in->width(), in->height(), in->channels());
    out->metadata() = in->metadata();
    for (const auto& c : in->channels())
        if (c.name != "R" && c.name != "G" && c.name != "B" && c.name != "A") utils::copyChannel(*in, *out, c);
    float* o[3] = {out->hostFloat("R"), out->hostFloat("G"), out->hostFloat("B")};
    float* oa = out->hostFloat("A");
    const int w = in->width();
    const float keep = 1.0f - amount;
    // Decided once, not per pixel.
    const bool multiply = mode == "multiply", blend = mode == "blend", add = mode == "add";

    ctx.parallelFor(0, in->height(), 8, [&](int y0, int y1) {
        for (std::size_t i = std::size_t(y0) * std::size_t(w); i < std::size_t(y1) * std::size_t(w); ++i) {
            float rgb[3] = {base.c[0][i], base.c[1][i], base.c[2][i]};
            float a = base.a ? base.a[i] : 1.0f;
            if (multiply) {
                // Lighting terms leave background and missing factors alone. The
                // lerp form gives exactly `factor` at amount 1 and exactly 1 at 0.
                const float f = factor[i];
                const bool background = depth && std::isinf(depth[i]) && depth[i] > 0;
                if (std::isfinite(f) && !background) {
                    const float m = keep + amount * f;
                    for (float& v : rgb) v *= m;
                }
            } else if (finiteColour(second, i)) {
                // A non-finite second colour (no data) never spreads into the result.
                const float oc[3] = {second.c[0][i], second.c[1][i], second.c[2][i]};
                const float oAlpha = second.a ? second.a[i] : 1.0f;
                if (blend) {
                    for (int k = 0; k < 3; ++k) rgb[k] = keep * rgb[k] + amount * oc[k];
                    a = keep * a + amount * oAlpha;
                } else if (add) {
                    for (int k = 0; k < 3; ++k) rgb[k] += amount * oc[k];
                } else {  // over, in premultiplied form, back to straight alpha
                    const float ao = std::fmin(std::fmax(oAlpha, 0.0f), 1.0f) * amount;
                    if (ao >= 1.0f) {
                        for (int k = 0; k < 3; ++k) rgb[k] = oc[k];
                        a = 1.0f;
                    } else if (ao > 0.0f) {
                        const float ai = std::isfinite(a) ? std::fmin(std::fmax(a, 0.0f), 1.0f) : 0.0f;
                        const float below = ai * (1.0f - ao);
                        const float outA = ao + below;
                        for (int k = 0; k < 3; ++k)
                            rgb[k] = (oc[k] * ao + (below > 0.0f ? rgb[k] * below : 0.0f)) / outA;
                        a = outA;
                    }
                }
            }
            for (int k = 0; k < 3; ++k) o[k][i] = rgb[k];
            if (oa) oa[i] = a;
        }
    });
    if (ctx.cancelled()) return;
    ctx.progress(1.0);
    ctx.setOutput("image", BufferPtr(std::move(out)));
}

}  // namespace darkroom
