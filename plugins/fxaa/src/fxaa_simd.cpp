#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/fxaa_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "fxaa_simd.h"
#include "luma.h"

#include <limits>

HWY_BEFORE_NAMESPACE();
namespace darkroom::fxaa {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DF = hn::ScalableTag<float>;
using VF = hn::Vec<DF>;

std::size_t LumaSpan(const float* r, const float* g, const float* b, const float* alpha, float* luma,
                     std::size_t begin, std::size_t end) {
    const DF df;
    const hn::RebindToSigned<DF> di;
    const std::size_t lanes = hn::Lanes(df);
    if (end - begin < lanes) return begin;
    const float* table = encodeTable();
    const VF zero = hn::Zero(df), one = hn::Set(df, 1.0f), entries = hn::Set(df, float(kEncodeEntries));
    const VF inf = hn::Set(df, std::numeric_limits<float>::infinity());
    const auto last = hn::Set(di, kEncodeEntries - 1);
    // encode (luma.cpp): clamp, sqrt, table entries i and i + 1, linear blend.
    auto encode = [&](VF c) {
        c = hn::IfThenElse(hn::Lt(c, zero), zero, hn::IfThenElse(hn::Lt(one, c), one, c));
        const VF s = hn::Mul(hn::Sqrt(c), entries);
        const auto i = hn::Min(hn::ConvertTo(di, s), last);
        const VF f = hn::Sub(s, hn::ConvertTo(df, i));
        const VF a = hn::GatherIndex(df, table, i), bb = hn::GatherIndex(df, table + 1, i);
        return hn::Add(a, hn::Mul(f, hn::Sub(bb, a)));
    };
    const VF nan = hn::Set(df, std::numeric_limits<float>::quiet_NaN());
    for (std::size_t i = begin;; i += lanes) {
        if (i + lanes > end) i = end - lanes;  // overlap the last vector: pixels are independent
        const VF vr = hn::LoadU(df, r + i), vg = hn::LoadU(df, g + i), vb = hn::LoadU(df, b + i);
        auto ok = hn::And(hn::And(hn::Lt(hn::Abs(vr), inf), hn::Lt(hn::Abs(vg), inf)), hn::Lt(hn::Abs(vb), inf));
        if (alpha) ok = hn::And(ok, hn::Gt(hn::LoadU(df, alpha + i), zero));
        // Lanes that are not blendable get NaN below; keep NaN out of the table index.
        auto encodeOk = [&](VF c) { return encode(hn::IfThenElseZero(ok, c)); };
        const VF y = hn::Add(hn::Add(hn::Mul(hn::Set(df, 0.299f), encodeOk(vr)), hn::Mul(hn::Set(df, 0.587f), encodeOk(vg))),
                             hn::Mul(hn::Set(df, 0.114f), encodeOk(vb)));
        hn::StoreU(hn::IfThenElse(ok, y, nan), df, luma + i);
        if (i + lanes == end) return end;
    }
}

int FlatSpan(const LumaPlane& plane, const Settings& s, const ColourRows& colour, int y, int x0, int x1,
             std::uint8_t* needsDecision) {
    const DF df;
    const hn::RebindToSigned<DF> di;
    const hn::Rebind<std::uint8_t, DF> d8;
    const int lanes = int(hn::Lanes(df));
    if (x1 - x0 < lanes) return x0;
    const std::size_t w = std::size_t(plane.width);
    const float* row = plane.luma + std::size_t(y) * w;
    const VF thresholdMin = hn::Set(df, s.edgeThresholdMin), threshold = hn::Set(df, s.edgeThreshold);
    const VF zero = hn::Zero(df);
    for (int x = x0;; x += lanes) {
        if (x + lanes > x1) x = x1 - lanes;  // overlap the last vector: pixels are independent
        const VF m = hn::LoadU(df, row + x);
        // Reader::at: a NaN neighbour reads as the centre.
        auto at = [&](const float* p) {
            const VF v = hn::LoadU(df, p);
            return hn::IfThenElse(hn::IsNaN(v), m, v);
        };
        const VF n = at(row + x - w), so = at(row + x + w), e = at(row + x + 1), wv = at(row + x - 1);
        const VF hi = hn::Max(hn::Max(hn::Max(m, n), hn::Max(so, e)), wv);
        const VF lo = hn::Min(hn::Min(hn::Min(m, n), hn::Min(so, e)), wv);
        const VF range = hn::Sub(hi, lo);
        const VF scaled = hn::Mul(hi, threshold);
        const VF needed = hn::IfThenElse(hn::Lt(thresholdMin, scaled), scaled, thresholdMin);
        const auto flat = hn::Or(hn::IsNaN(m), hn::Or(hn::Lt(range, needed), hn::Not(hn::Gt(range, zero))));
        const std::size_t i = std::size_t(y) * w + std::size_t(x);
        for (int c = 0; c < 4; ++c)
            if (colour.in[c]) hn::StoreU(hn::LoadU(df, colour.in[c] + i), df, colour.out[c] + i);
        const auto decide = hn::And(hn::VecFromMask(di, hn::RebindMask(di, hn::Not(flat))), hn::Set(di, 1));
        hn::StoreU(hn::DemoteTo(d8, decide), d8, needsDecision + x);
        if (x + lanes == x1) return x1;
    }
}

}  // namespace HWY_NAMESPACE
}  // namespace darkroom::fxaa
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace darkroom::fxaa {
HWY_EXPORT(LumaSpan);
HWY_EXPORT(FlatSpan);
std::size_t lumaSpan(const float* r, const float* g, const float* b, const float* alpha, float* luma,
                     std::size_t begin, std::size_t end) {
    return HWY_DYNAMIC_DISPATCH(LumaSpan)(r, g, b, alpha, luma, begin, end);
}
int flatSpan(const LumaPlane& plane, const Settings& s, const ColourRows& colour, int y, int x0, int x1,
             std::uint8_t* needsDecision) {
    return HWY_DYNAMIC_DISPATCH(FlatSpan)(plane, s, colour, y, x0, x1, needsDecision);
}
}  // namespace darkroom::fxaa
#endif
