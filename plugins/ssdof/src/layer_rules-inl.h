// The rules of layers.h for a vector of pixels, shared by the gathers' SIMD
// code (a Highway per-target header: included once per instruction set).
//
// Per sample q of pixel p (signed CoCs sp, sq; distance t):
//   near layer:  q is in the near field (sq <= -0.5), not behind a near p by
//                more than kSameLayer, and its CoC reaches p (t <= |sq| + 0.5);
//   focus/far layer: for a near p, samples behind it (sq > sp + kSameLayer)
//                within |sp| + 0.5, weight 1; otherwise samples not in front
//                of p (sq >= sp - kSameLayer) within min(|sq|, |sp|) + 0.5,
//                weight 1 / max(min(|sq|, |sp|), 0.5)^2.
#if defined(DARKROOM_SSDOF_LAYER_RULES_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef DARKROOM_SSDOF_LAYER_RULES_INL_H_
#undef DARKROOM_SSDOF_LAYER_RULES_INL_H_
#else
#define DARKROOM_SSDOF_LAYER_RULES_INL_H_
#endif

#include "layers.h"

#include <hwy/highway.h>

#include <algorithm>
#include <cstring>

HWY_BEFORE_NAMESPACE();
namespace darkroom::ssdof {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DF = hn::ScalableTag<float>;
using DI = hn::RebindToSigned<DF>;
using VF = hn::Vec<DF>;
using VI = hn::Vec<DI>;
using MF = hn::Mask<DF>;

// std::round / std::lround of a float: half away from zero, exactly.
HWY_INLINE VF RoundHalfAway(VF v) {
    const DF d;
    const VF whole = hn::Trunc(v);
    const VF rest = hn::Sub(v, whole);  // exact
    return hn::IfThenElse(hn::Ge(hn::Abs(rest), hn::Set(d, 0.5f)), hn::Add(whole, hn::CopySign(hn::Set(d, 1.0f), v)), whole);
}

// reachesAsNear: q reaches p through the near layer.
HWY_INLINE MF ReachesAsNear(VF sp, VF sq, VF t) {
    const DF d;
    const VF focus = hn::Set(d, -kInFocus);
    const MF nearQ = hn::Not(hn::Gt(sq, focus));
    const MF behindNearP = hn::And(hn::Le(sp, focus), hn::Gt(sq, hn::Add(sp, hn::Set(d, kSameLayer))));
    return hn::AndNot(behindNearP, hn::And(nearQ, hn::Le(t, hn::Add(hn::Neg(sq), hn::Set(d, 0.5f)))));
}

// backgroundWeight: q's weight in p's focus/far layer (0: not in it). sq must
// not be NaN (the caller masks taps outside the image).
HWY_INLINE VF BackgroundWeight(VF sp, VF rp, VF sq, VF t) {
    const DF d;
    const VF half = hn::Set(d, 0.5f), one = hn::Set(d, 1.0f), same = hn::Set(d, kSameLayer);
    const VF behind = hn::IfThenElseZero(hn::And(hn::Gt(sq, hn::Add(sp, same)), hn::Le(t, hn::Add(rp, half))), one);
    const VF c = hn::Min(hn::Abs(sq), rp);
    const VF cc = hn::Max(c, hn::Set(d, kInFocus));
    const MF reaches = hn::And(hn::Not(hn::Lt(sq, hn::Sub(sp, same))), hn::Not(hn::Gt(t, hn::Add(c, half))));
    const VF around = hn::IfThenElseZero(reaches, hn::Div(one, hn::Mul(cc, cc)));
    return hn::IfThenElse(hn::Le(sp, hn::Set(d, -kInFocus)), behind, around);
}

// A layer's running sums: premultiplied colour times weight, and the weights.
struct Layer {
    VF r, g, b, a, weight;
    static Layer zero() {
        const VF z = hn::Zero(DF());
        return {z, z, z, z, z};
    }
    // Rgba::add: sum += weight * colour (a weight of +0 leaves the sums as they are).
    HWY_INLINE void add(VF w, VF cr, VF cg, VF cb, VF ca) {
        r = hn::Add(r, hn::Mul(w, cr));
        g = hn::Add(g, hn::Mul(w, cg));
        b = hn::Add(b, hn::Mul(w, cb));
        a = hn::Add(a, hn::Mul(w, ca));
        weight = hn::Add(weight, w);
    }
    // Adds partial sums (colour and weight, Rgba::add with weight 1) where `use` is set.
    template <class At>
    HWY_INLINE void addWhere(MF use, const At& at) {
        r = hn::Add(r, hn::IfThenElseZero(use, at(0)));
        g = hn::Add(g, hn::IfThenElseZero(use, at(1)));
        b = hn::Add(b, hn::IfThenElseZero(use, at(2)));
        a = hn::Add(a, hn::IfThenElseZero(use, at(3)));
        weight = hn::Add(weight, hn::IfThenElseZero(use, at(4)));
    }
};

// composite (alpha_F = min(1, near weight)) and the straight-alpha output of
// `count` pixels from output index i; in-focus pixels with no near light
// (`unchanged`) keep the input's bits.
HWY_INLINE void Finish(const Output& o, std::size_t i, int count, const Layer& nearL, const Layer& backL, VF sr, VF sg,
                       VF sb, VF sa, MF unchanged) {
    const DF d;
    const VF zero = hn::Zero(d), one = hn::Set(d, 1.0f);
    const VF alpha = hn::Min(nearL.weight, one);
    const MF covered = hn::Gt(alpha, zero);
    const VF k1 = hn::Div(alpha, nearL.weight);
    const MF behind = hn::Gt(backL.weight, zero);
    const VF rest = hn::Sub(one, alpha);
    const VF k2 = hn::IfThenElse(behind, hn::Div(rest, backL.weight), rest);
    auto mix = [&](VF n, VF b, VF self) {
        const VF first = hn::IfThenElse(covered, hn::Add(zero, hn::Mul(k1, n)), zero);
        return hn::Add(first, hn::Mul(k2, hn::IfThenElse(behind, b, self)));
    };
    const VF cr = mix(nearL.r, backL.r, sr), cg = mix(nearL.g, backL.g, sg), cb = mix(nearL.b, backL.b, sb);
    const VF ca = mix(nearL.a, backL.a, sa);
    const bool straight = o.in[3] != nullptr;
    const VF inv = hn::IfThenElse(hn::Gt(ca, zero), hn::Div(one, ca), zero);
    VF channel[4] = {straight ? hn::Mul(cr, inv) : cr, straight ? hn::Mul(cg, inv) : cg, straight ? hn::Mul(cb, inv) : cb,
                     hn::IfThenElse(hn::Lt(one, ca), one, ca)};
    const std::size_t lanes = hn::Lanes(d);
    for (int c = 0; c < 4; ++c) {
        if (!o.out[c]) continue;
        if (count == int(lanes)) {
            const VF kept = hn::LoadU(d, o.in[c] + i);
            hn::StoreU(hn::IfThenElse(unchanged, kept, channel[c]), d, o.out[c] + i);
        } else {
            // The last pixels of a row: only `count` lanes are in the image.
            float value[64], keep[64];
            hn::StoreU(channel[c], d, value);
            hn::StoreU(hn::IfThenElseZero(unchanged, one), d, keep);
            for (int k = 0; k < count; ++k) o.out[c][i + std::size_t(k)] = keep[k] != 0.0f ? o.in[c][i + std::size_t(k)] : value[k];
        }
    }
}

}  // namespace HWY_NAMESPACE
}  // namespace darkroom::ssdof
HWY_AFTER_NAMESPACE();

#endif  // include guard
