#include "mix.h"

#include "image_checks.h"
#include "mix_kernel.h"

#include <darkroom/error.h>

#include <algorithm>
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

}  // namespace

namespace utils {

void mixAt(const MixJob& job, std::size_t i) {
    float rgb[3] = {job.base[0][i], job.base[1][i], job.base[2][i]};
    float a = job.base[3] ? job.base[3][i] : 1.0f;
    const float amount = job.amount, keep = job.keep;
    if (job.op == MixOp::Multiply) {
        // Lighting terms leave background and missing factors alone. The
        // lerp form gives exactly `factor` at amount 1 and exactly 1 at 0.
        const float f = job.factor[i];
        const bool background = job.depth && std::isinf(job.depth[i]) && job.depth[i] > 0;
        if (std::isfinite(f) && !background) {
            const float m = keep + amount * f;
            for (float& v : rgb) v *= m;
        }
    } else if (std::isfinite(job.second[0][i]) && std::isfinite(job.second[1][i]) && std::isfinite(job.second[2][i]) &&
               (!job.second[3] || std::isfinite(job.second[3][i]))) {
        // A non-finite second colour (no data) never spreads into the result.
        const float oc[3] = {job.second[0][i], job.second[1][i], job.second[2][i]};
        const float oAlpha = job.second[3] ? job.second[3][i] : 1.0f;
        if (job.op == MixOp::Blend) {
            for (int k = 0; k < 3; ++k) rgb[k] = keep * rgb[k] + amount * oc[k];
            a = keep * a + amount * oAlpha;
        } else if (job.op == MixOp::Add) {
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
                for (int k = 0; k < 3; ++k) rgb[k] = (oc[k] * ao + (below > 0.0f ? rgb[k] * below : 0.0f)) / outA;
                a = outA;
            }
        }
    }
    for (int k = 0; k < 3; ++k) job.out[k][i] = rgb[k];
    if (job.out[3]) job.out[3][i] = a;
}

}  // namespace utils

void Mix::execute(Context& ctx) {
    const BufferPtr in = ctx.get(image_);
    const BufferPtr other = ctx.get(other_);
    const Mode mode = ctx.get(mode_);
    const float amount = float(ctx.get(amount_));
    if (other) utils::requireSameSize(*in, *other, "image", "other");
    const Rgba base = colourOf(*in, "image");

    utils::MixJob job;
    job.amount = amount;
    job.keep = 1.0f - amount;
    std::copy(base.c, base.c + 3, job.base);
    job.base[3] = base.a;
    if (mode == Mode::Multiply) {
        job.op = utils::MixOp::Multiply;
        job.factor = utils::requireFloatChannel(other ? *other : *in, ctx.get(factorChannel_), other ? "other" : "image");
        job.depth = in->hostFloat("Z");
    } else {
        if (!other) throw Error("mode '" + ctx.getString(mode_.name()) + "' needs an image on 'other'");
        const Rgba second = colourOf(*other, "other");
        std::copy(second.c, second.c + 3, job.second);
        job.second[3] = second.a;
        job.op = mode == Mode::Blend ? utils::MixOp::Blend : mode == Mode::Add ? utils::MixOp::Add : utils::MixOp::Over;
    }

    // New colour (and alpha when the input has it), every pixel written; the
    // rest is shared.
    std::vector<ChannelDesc> fresh{"R", "G", "B"};
    if (base.a) fresh.push_back("A");
    auto out = ctx.derive(in, fresh, Fill::None);
    job.out[0] = out->writeFloat("R");
    job.out[1] = out->writeFloat("G");
    job.out[2] = out->writeFloat("B");
    job.out[3] = base.a ? out->writeFloat("A") : nullptr;
    const std::size_t w = std::size_t(in->width());
    ctx.parallelFor(0, in->height(), 8, [&](int y0, int y1) {
        const std::size_t end = std::size_t(y1) * w;
        for (std::size_t i = utils::mixSpan(job, std::size_t(y0) * w, end); i < end; ++i) utils::mixAt(job, i);
    });
    ctx.progress(1.0);
    ctx.set(result_, out);
}

}  // namespace darkroom
