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

Rgba colourOf(const Buffer& b, const std::string& port) {
    Rgba r;
    const char* names[3] = {"R", "G", "B"};
    for (int k = 0; k < 3; ++k) r.c[k] = utils::requireFloatChannel(b, names[k], port);
    r.a = b.hostFloat("A");
    return r;
}

bool finiteColour(const Rgba& c, std::size_t i) {
    return std::isfinite(c.c[0][i]) && std::isfinite(c.c[1][i]) && std::isfinite(c.c[2][i]) &&
           (!c.a || std::isfinite(c.a[i]));
}

}  // namespace

void Mix::execute(Context& ctx) {
    const BufferPtr in = ctx.get(image_);
    const BufferPtr other = ctx.get(other_);
    const Mode mode = ctx.get(mode_);
    const float amount = float(ctx.get(amount_));
    if (other) utils::requireSameSize(*in, *other, "image", "other");
    const Rgba base = colourOf(*in, "image");
    const float* depth = in->hostFloat("Z");

    const float* factor = nullptr;
    Rgba second;
    if (mode == Mode::Multiply) {
        factor = utils::requireFloatChannel(other ? *other : *in, ctx.get(factorChannel_), other ? "other" : "image");
    } else {
        if (!other) throw Error("mode '" + ctx.getString(mode_.name()) + "' needs an image on 'other'");
        second = colourOf(*other, "other");
    }

    // New colour (and alpha when the input has it), every pixel written; the
    // rest is shared.
    std::vector<ChannelDesc> fresh{"R", "G", "B"};
    if (base.a) fresh.push_back("A");
    auto out = ctx.derive(in, fresh, Fill::None);
    float* o[3] = {out->writeFloat("R"), out->writeFloat("G"), out->writeFloat("B")};
    float* oa = base.a ? out->writeFloat("A") : nullptr;
    const int w = in->width();
    const float keep = 1.0f - amount;
    const bool multiply = mode == Mode::Multiply, blend = mode == Mode::Blend, add = mode == Mode::Add;

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
    ctx.progress(1.0);
    ctx.set(result_, out);
}

}  // namespace darkroom
