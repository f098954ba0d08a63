// mixAt (mix.cpp) for a vector of pixels at a time.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/mix_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "mix_kernel.h"

#include <limits>

HWY_BEFORE_NAMESPACE();
namespace darkroom::utils {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

std::size_t MixSpan(const MixJob& job, std::size_t begin, std::size_t end) {
    const hn::ScalableTag<float> d;
    using V = hn::Vec<decltype(d)>;
    const std::size_t lanes = hn::Lanes(d);
    if (end - begin < lanes) return begin;
    const V amount = hn::Set(d, job.amount), keep = hn::Set(d, job.keep);
    const V zero = hn::Zero(d), one = hn::Set(d, 1.0f), inf = hn::Set(d, std::numeric_limits<float>::infinity());
    auto finite = [&](V v) { return hn::Lt(hn::Abs(v), inf); };
    // std::fmin(std::fmax(v, 0), 1) for a finite v (signed zeros aside, which
    // only ever meet comparisons and additions to non-zero values below).
    auto unit = [&](V v) { return hn::Min(hn::Max(v, zero), one); };
    for (std::size_t i = begin;; i += lanes) {
        if (i + lanes > end) i = end - lanes;  // overlap the last vector: pixels are independent
        V rgb[3] = {hn::LoadU(d, job.base[0] + i), hn::LoadU(d, job.base[1] + i), hn::LoadU(d, job.base[2] + i)};
        V a = job.base[3] ? hn::LoadU(d, job.base[3] + i) : one;
        if (job.op == MixOp::Multiply) {
            const V f = hn::LoadU(d, job.factor + i);
            auto apply = finite(f);
            if (job.depth) apply = hn::AndNot(hn::Eq(hn::LoadU(d, job.depth + i), inf), apply);
            const V m = hn::Add(keep, hn::Mul(amount, f));
            for (V& v : rgb) v = hn::IfThenElse(apply, hn::Mul(v, m), v);
        } else {
            const V oc[3] = {hn::LoadU(d, job.second[0] + i), hn::LoadU(d, job.second[1] + i),
                             hn::LoadU(d, job.second[2] + i)};
            const V oAlpha = job.second[3] ? hn::LoadU(d, job.second[3] + i) : one;
            auto ok = hn::And(hn::And(finite(oc[0]), finite(oc[1])), hn::And(finite(oc[2]), finite(oAlpha)));
            if (job.op == MixOp::Blend) {
                for (int k = 0; k < 3; ++k)
                    rgb[k] = hn::IfThenElse(ok, hn::Add(hn::Mul(keep, rgb[k]), hn::Mul(amount, oc[k])), rgb[k]);
                a = hn::IfThenElse(ok, hn::Add(hn::Mul(keep, a), hn::Mul(amount, oAlpha)), a);
            } else if (job.op == MixOp::Add) {
                for (int k = 0; k < 3; ++k) rgb[k] = hn::IfThenElse(ok, hn::Add(rgb[k], hn::Mul(amount, oc[k])), rgb[k]);
            } else {
                const V ao = hn::Mul(unit(oAlpha), amount);
                const auto full = hn::And(ok, hn::Ge(ao, one));
                const auto part = hn::AndNot(full, hn::And(ok, hn::Gt(ao, zero)));
                const V ai = hn::IfThenElseZero(finite(a), unit(a));
                const V below = hn::Mul(ai, hn::Sub(one, ao));
                const V outA = hn::Add(ao, below);
                const auto under = hn::Gt(below, zero);
                for (int k = 0; k < 3; ++k) {
                    const V mixed = hn::Div(hn::Add(hn::Mul(oc[k], ao), hn::IfThenElseZero(under, hn::Mul(rgb[k], below))), outA);
                    rgb[k] = hn::IfThenElse(full, oc[k], hn::IfThenElse(part, mixed, rgb[k]));
                }
                a = hn::IfThenElse(full, one, hn::IfThenElse(part, outA, a));
            }
        }
        for (int k = 0; k < 3; ++k) hn::StoreU(rgb[k], d, job.out[k] + i);
        if (job.out[3]) hn::StoreU(a, d, job.out[3] + i);
        if (i + lanes == end) return end;
    }
}

}  // namespace HWY_NAMESPACE
}  // namespace darkroom::utils
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace darkroom::utils {
HWY_EXPORT(MixSpan);
std::size_t mixSpan(const MixJob& job, std::size_t begin, std::size_t end) {
    return HWY_DYNAMIC_DISPATCH(MixSpan)(job, begin, end);
}
}  // namespace darkroom::utils
#endif
