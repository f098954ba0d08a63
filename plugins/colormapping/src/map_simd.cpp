// mapValue (color_mapping.cpp) and the finite range for a vector of pixels at
// a time.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/map_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "map_kernel.h"

#include <algorithm>
#include <cmath>
#include <limits>

HWY_BEFORE_NAMESPACE();
namespace darkroom::colormapping {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using D = hn::ScalableTag<double>;
using DF = hn::Rebind<float, D>;
using DI = hn::Rebind<std::int32_t, D>;
using V = hn::Vec<D>;

std::size_t MapSpan(const MapJob& job, const float* values, std::size_t begin, std::size_t end) {
    const D d;
    const DF df;
    const DI di;
    const std::size_t lanes = hn::Lanes(d);
    if (end - begin < lanes) return begin;
    const V low = hn::Set(d, job.low), span = hn::Set(d, job.high - job.low);
    const V zero = hn::Zero(d), one = hn::Set(d, 1.0), half = hn::Set(d, 0.5);
    const bool flat = job.high == job.low;
    const V last = hn::Set(d, double(kTableSize - 1));
    const auto lastIndex = hn::Set(di, kTableSize - 2);
    const hn::Rebind<std::uint64_t, D> du64;
    const hn::Rebind<std::uint32_t, D> du32;
    const auto nanColour = [&](int c) { return hn::Set(df, (&job.nan.r)[c]); };
    const auto inf = hn::Set(df, std::numeric_limits<float>::infinity());
    for (std::size_t i = begin;; i += lanes) {
        // The last vector ends at `end`, overlapping the one before (pixels
        // are independent: the overlap is computed twice alike).
        if (i + lanes > end) i = end - lanes;
        const auto vf = hn::LoadU(df, values + i);
        const V v = hn::PromoteTo(d, vf);
        const auto background = job.depth ? hn::Eq(hn::LoadU(df, job.depth + i), inf) : hn::FirstN(df, 0);
        if (job.depth && hn::AllTrue(df, background)) {
            // Nothing but background (most vectors of a rendered picture:
            // 84 % of the pixels of the demo's isosurface at 2048²): the
            // zeros every lane would get, without the lookups.
            for (int c = 0; c < 4; ++c) hn::StoreU(hn::Zero(df), df, job.out[c] + i);
            if (i + lanes == end) return end;
            continue;
        }
        const auto isNan = job.haveRange ? hn::IsNaN(vf) : hn::FirstN(df, lanes);
        V p;
        if (flat) {
            p = hn::IfThenElse(hn::Lt(v, low), zero, hn::IfThenElse(hn::Gt(v, low), one, half));
        } else {  // std::clamp(x, 0, 1): x < 0 ? 0 : (1 < x ? 1 : x)
            const V x = hn::Div(hn::Sub(v, low), span);
            p = hn::IfThenElse(hn::Lt(x, zero), zero, hn::IfThenElse(hn::Lt(one, x), one, x));
        }
        const V f = hn::Mul(p, last);
        // NaN lanes take the NaN colour below; keep their index in range.
        const auto k = hn::Min(hn::DemoteTo(di, hn::IfThenElse(hn::Eq(f, f), f, zero)), lastIndex);
        const auto t = hn::DemoteTo(df, hn::Sub(f, hn::PromoteTo(d, k)));
        const auto s = hn::Sub(hn::Set(df, 1.0f), t);
        const auto at = hn::PromoteTo(hn::Rebind<std::int64_t, D>(), k);
        for (int c = 0; c < 3; ++c) {
            const auto pair = hn::GatherIndex(du64, job.pairs[c], at);
            const auto a = hn::BitCast(df, hn::TruncateTo(du32, pair));
            const auto b = hn::BitCast(df, hn::TruncateTo(du32, hn::ShiftRight<32>(pair)));
            auto colour = hn::Add(hn::Mul(s, a), hn::Mul(t, b));
            colour = hn::IfThenElse(isNan, nanColour(c), colour);
            hn::StoreU(hn::IfThenZeroElse(background, colour), df, job.out[c] + i);
        }
        const auto alpha = hn::IfThenElse(isNan, nanColour(3), hn::Set(df, job.alpha));
        hn::StoreU(hn::IfThenZeroElse(background, alpha), df, job.out[3] + i);
        if (i + lanes == end) return end;
    }
}

MinMax RangeSpan(const float* values, const float* depth, std::size_t begin, std::size_t end) {
    const hn::ScalableTag<float> df;
    const std::size_t lanes = hn::Lanes(df);
    const auto inf = hn::Set(df, std::numeric_limits<float>::infinity());
    auto lo = inf, hi = hn::Neg(inf);
    auto any = hn::FirstN(df, 0);
    std::size_t i = begin;
    auto add = [&](auto v, auto use) {
        use = hn::And(use, hn::Lt(hn::Abs(v), inf));  // finite
        any = hn::Or(any, use);
        lo = hn::Min(lo, hn::IfThenElse(use, v, inf));
        hi = hn::Max(hi, hn::IfThenElse(use, v, hn::Neg(inf)));
    };
    for (; i + lanes <= end; i += lanes) {
        const auto v = hn::LoadU(df, values + i);
        add(v, depth ? hn::Ne(hn::LoadU(df, depth + i), inf) : hn::FirstN(df, lanes));
    }
    MinMax r{std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(), !hn::AllFalse(df, any)};
    if (r.found) {
        r.low = hn::GetLane(hn::MinOfLanes(df, lo));
        r.high = hn::GetLane(hn::MaxOfLanes(df, hi));
    }
    for (; i < end; ++i) {
        const float v = values[i];
        if ((depth && depth[i] == std::numeric_limits<float>::infinity()) || !std::isfinite(v)) continue;
        r.found = true;
        r.low = std::min(r.low, v);
        r.high = std::max(r.high, v);
    }
    return r;
}

}  // namespace HWY_NAMESPACE
}  // namespace darkroom::colormapping
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace darkroom::colormapping {
HWY_EXPORT(MapSpan);
HWY_EXPORT(RangeSpan);
std::size_t mapSpan(const MapJob& job, const float* values, std::size_t begin, std::size_t end) {
    return HWY_DYNAMIC_DISPATCH(MapSpan)(job, values, begin, end);
}
MinMax rangeSpan(const float* values, const float* depth, std::size_t begin, std::size_t end) {
    return HWY_DYNAMIC_DISPATCH(RangeSpan)(values, depth, begin, end);
}
}  // namespace darkroom::colormapping
#endif
