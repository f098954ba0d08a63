// The last step of SSAO: AO = clamp(1 - intensity (1 - AO))^power, 1 where
// there is no surface, copied from the padded plane into the output channel.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "finish.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include "finish.h"
#include "simd-inl.h"

#include <hwy/contrib/math/math-inl.h>
#include <hwy/highway.h>

#include <cmath>
#include <limits>

HWY_BEFORE_NAMESPACE();
namespace darkroom::ssao::HWY_NAMESPACE {

void FinishRow(const Frame& g, const float* raw, float intensity, float power, int y, float* out) {
    const DF d;
    const int N = int(hn::Lanes(d));
    const std::size_t row = g.offset(0, y);
    const VF zero = hn::Zero(d), one = hn::Set(d, 1.0f), vi = hn::Set(d, intensity), vp = hn::Set(d, power);
    const VF inf = hn::Set(d, std::numeric_limits<float>::infinity());
    alignas(64) float tail[64];
    for (int x = 0; x < g.width(); x += N) {
        VF a = hn::Min(hn::Max(hn::NegMulAdd(vi, hn::Sub(one, hn::Load(d, raw + row + x)), one), zero), one);
        // a^power for a in [0, 1]; 0^power = 0 (power >= 0.1).
        if (power != 1.0f) a = hn::IfThenElseZero(hn::Gt(a, zero), hn::Exp(d, hn::Mul(vp, hn::Log(d, a))));
        const MF keep = hn::And(hn::Lt(hn::Load(d, g.z + row + x), inf), hn::IsFinite(a));
        const VF v = hn::IfThenElse(keep, a, one);
        if (x + N <= g.width()) {
            hn::StoreU(v, d, out + x);
        } else {
            hn::Store(v, d, tail);
            for (int i = 0; x + i < g.width(); ++i) out[x + i] = tail[i];
        }
    }
}

}  // namespace darkroom::ssao::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace darkroom::ssao {

HWY_EXPORT(FinishRow);

void finishRows(const Frame& g, const float* raw, float intensity, float power, int y0, int y1, float* out) {
    for (int y = y0; y < y1; ++y)
        HWY_DYNAMIC_DISPATCH(FinishRow)(g, raw, intensity, power, y, out + std::size_t(y) * std::size_t(g.width()));
}

}  // namespace darkroom::ssao
#endif  // HWY_ONCE
