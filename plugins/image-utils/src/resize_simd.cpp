// resampleAt and nearestDepthSource (resize.cpp) for a vector of output
// pixels of a row at a time: the x taps padded to one count, the same double
// sums in the same order.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/resize_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "resize_kernel.h"

#include <limits>

HWY_BEFORE_NAMESPACE();
namespace darkroom::utils {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using D = hn::ScalableTag<double>;
using DF = hn::Rebind<float, D>;
using DI = hn::Rebind<std::int32_t, D>;
using V = hn::Vec<D>;

int ResampleRow(const ResizeRow& row, const PaddedTaps& px, const float* src, const float* weightBy, float* out) {
    const D d;
    const DF df;
    const DI di;
    const int lanes = int(hn::Lanes(d));
    const int w = row.outputWidth;
    if (w < lanes) return 0;
    const V zero = hn::Zero(d);
    const V inf = hn::Set(d, std::numeric_limits<double>::infinity());
    for (int x = 0;; x += lanes) {
        if (x + lanes > w) x = w - lanes;  // overlap the last vector: pixels are independent
        V sumA = zero, weightA = zero, sum = zero, weight = zero;
        for (const Tap* sy = row.yBegin; sy != row.yEnd; ++sy) {
            const float* line = src + std::size_t(sy->index) * std::size_t(row.sourceWidth);
            const float* alphaLine = weightBy ? weightBy + std::size_t(sy->index) * std::size_t(row.sourceWidth) : nullptr;
            const V wy = hn::Set(d, sy->weight);
            for (int k = 0; k < px.count; ++k) {
                const std::size_t at = std::size_t(k) * std::size_t(w) + std::size_t(x);
                const auto idx = hn::LoadU(di, px.index.data() + at);
                const V wx = hn::LoadU(d, px.weight.data() + at);
                const V v = hn::PromoteTo(d, hn::GatherIndex(df, line, idx));
                // Padding taps and NaN or infinite samples (no data) are never averaged in.
                const auto use = hn::And(hn::Gt(wx, zero), hn::Lt(hn::Abs(v), inf));
                const V wt = hn::Mul(wy, wx);
                sum = hn::IfThenElse(use, hn::Add(sum, hn::Mul(wt, v)), sum);
                weight = hn::IfThenElse(use, hn::Add(weight, wt), weight);
                if (alphaLine) {
                    const V a = hn::PromoteTo(d, hn::GatherIndex(df, alphaLine, idx));
                    const auto useA = hn::And(use, hn::And(hn::Gt(a, zero), hn::Lt(a, inf)));
                    const V wa = hn::Mul(wt, a);
                    sumA = hn::IfThenElse(useA, hn::Add(sumA, hn::Mul(wa, v)), sumA);
                    weightA = hn::IfThenElse(useA, hn::Add(weightA, wa), weightA);
                }
            }
        }
        const V nan = hn::Set(d, std::numeric_limits<double>::quiet_NaN());
        V value = hn::IfThenElse(hn::Gt(weight, zero), hn::Div(sum, weight), nan);
        if (weightBy) value = hn::IfThenElse(hn::Gt(weightA, zero), hn::Div(sumA, weightA), value);
        hn::StoreU(hn::DemoteTo(df, value), df, out + x);
        if (x + lanes == w) return w;
    }
}

int NearestDepthRow(const ResizeRow& row, const PaddedTaps& px, const float* depth, const std::int32_t* fallback,
                    std::int32_t* source) {
    const hn::ScalableTag<float> df;
    const hn::RebindToSigned<decltype(df)> di;
    const int lanes = int(hn::Lanes(df));
    const int w = row.outputWidth;
    if (w < lanes) return 0;
    const auto inf = hn::Set(df, std::numeric_limits<float>::infinity());
    for (int x = 0;; x += lanes) {
        if (x + lanes > w) x = w - lanes;
        auto best = inf;
        auto who = hn::LoadU(di, fallback + x);
        for (const Tap* sy = row.yBegin; sy != row.yEnd; ++sy) {
            const auto rowStart = hn::Set(di, sy->index * row.sourceWidth);
            // Padding repeats a pixel's first tap, which can never be strictly nearer again.
            for (int k = 0; k < px.count; ++k) {
                const auto idx = hn::Add(rowStart, hn::LoadU(di, px.index.data() + std::size_t(k) * std::size_t(w) + std::size_t(x)));
                const auto z = hn::GatherIndex(df, depth, idx);
                const auto nearer = hn::And(hn::Lt(z, best), hn::Lt(hn::Abs(z), inf));
                best = hn::IfThenElse(nearer, z, best);
                who = hn::IfThenElse(hn::RebindMask(di, nearer), idx, who);
            }
        }
        hn::StoreU(who, di, source + x);
        if (x + lanes == w) return w;
    }
}

int GatherRow(const std::uint32_t* src, const std::int32_t* source, int width, std::uint32_t* out) {
    const hn::ScalableTag<std::uint32_t> du;
    const hn::RebindToSigned<decltype(du)> di;
    const int lanes = int(hn::Lanes(du));
    if (width < lanes) return 0;
    for (int x = 0;; x += lanes) {
        if (x + lanes > width) x = width - lanes;
        hn::StoreU(hn::GatherIndex(du, src, hn::LoadU(di, source + x)), du, out + x);
        if (x + lanes == width) return width;
    }
}

}  // namespace HWY_NAMESPACE
}  // namespace darkroom::utils
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace darkroom::utils {
HWY_EXPORT(ResampleRow);
HWY_EXPORT(NearestDepthRow);
HWY_EXPORT(GatherRow);
int resampleRow(const ResizeRow& row, const PaddedTaps& px, const float* src, const float* weightBy, float* out) {
    return HWY_DYNAMIC_DISPATCH(ResampleRow)(row, px, src, weightBy, out);
}
int nearestDepthRow(const ResizeRow& row, const PaddedTaps& px, const float* depth, const std::int32_t* fallback,
                    std::int32_t* source) {
    return HWY_DYNAMIC_DISPATCH(NearestDepthRow)(row, px, depth, fallback, source);
}
int gatherRow(const std::uint32_t* src, const std::int32_t* source, int width, std::uint32_t* out) {
    return HWY_DYNAMIC_DISPATCH(GatherRow)(src, source, width, out);
}
}  // namespace darkroom::utils
#endif
