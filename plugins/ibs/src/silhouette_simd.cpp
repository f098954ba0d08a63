// silhouetteAt (silhouette.cpp) for a vector of pixels of a row at a time:
// the same comparisons, in double where the per-pixel code uses double.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/silhouette_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "silhouette.h"

#include <limits>

HWY_BEFORE_NAMESPACE();
namespace darkroom::passes {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using D = hn::ScalableTag<double>;
using DF = hn::Rebind<float, D>;
using DI = hn::Rebind<std::int32_t, D>;
using V = hn::Vec<D>;
using M = hn::Mask<D>;

// Ids as doubles, ordered like the unsigned ids (flipping the top bit maps
// unsigned to signed order; every int32 is exact in a double).
V loadIds(const std::uint32_t* p) {
    const DI di;
    const auto u = hn::LoadU(di, reinterpret_cast<const std::int32_t*>(p));
    return hn::PromoteTo(D(), hn::Xor(u, hn::Set(di, std::numeric_limits<std::int32_t>::min())));
}

// nearOfEdge (silhouette.cpp) per lane, for pixels that both have data.
M nearOfEdge(V zp, V zq, V ip, V iq, bool useIds, V threshold) {
    const D d;
    const V inf = hn::Set(d, std::numeric_limits<double>::infinity());
    const M farther = hn::Lt(hn::Mul(threshold, hn::Abs(zp)), hn::Sub(zq, zp));
    M edge = farther;
    if (useIds) edge = hn::Or(edge, hn::And(hn::Ne(ip, iq), hn::Or(hn::Lt(zp, zq), hn::Lt(ip, iq))));
    edge = hn::AndNot(hn::Gt(zp, zq), edge);
    edge = hn::Or(hn::Eq(zq, inf), edge);
    return hn::AndNot(hn::Eq(zp, inf), edge);
}

int Span(const SilhouetteJob& job, int y, int x0, int x1) {
    const D d;
    const DF df;
    const int lanes = int(hn::Lanes(d));
    if (x1 - x0 < lanes) return x0;
    const int w = job.width;
    const bool useIds = job.ids != nullptr;
    const V threshold = hn::Set(d, job.threshold);
    const V minusInf = hn::Set(d, -std::numeric_limits<double>::infinity());
    auto hasData = [&](V z) { return hn::AndNot(hn::Eq(z, minusInf), hn::Eq(z, z)); };
    const V zero = hn::Zero(d);
    for (int x = x0;; x += lanes) {
        // The last vector ends at x1, overlapping the one before: pixels are
        // independent, so computing one twice gives the same value.
        if (x + lanes > x1) x = x1 - lanes;
        const std::size_t i = std::size_t(y) * w + x;
        const V zp = hn::PromoteTo(d, hn::LoadU(df, job.depth + i));
        const V ip = useIds ? loadIds(job.ids + i) : zero;
        const M pOk = hasData(zp);
        M edge = hn::FirstN(d, 0);
        for (const auto& [dx, dy] : job.disk) {
            const int qy = y + dy;
            if (qy < 0 || qy >= job.height) continue;
            const std::size_t j = std::size_t(qy) * w + std::size_t(x + dx);
            const V zq = hn::PromoteTo(d, hn::LoadU(df, job.depth + j));
            const V iq = useIds ? loadIds(job.ids + j) : zero;
            const M e = job.nearSide ? nearOfEdge(zp, zq, ip, iq, useIds, threshold)
                                     : nearOfEdge(zq, zp, iq, ip, useIds, threshold);
            edge = hn::Or(edge, hn::And(hasData(zq), e));
        }
        const V s = hn::IfThenElseZero(hn::And(pOk, edge), hn::Set(d, 1.0));
        hn::StoreU(hn::DemoteTo(df, s), df, job.out + i);
        if (x + lanes == x1) return x1;
    }
}

}  // namespace HWY_NAMESPACE
}  // namespace darkroom::passes
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace darkroom::passes {
HWY_EXPORT(Span);
int silhouetteSpan(const SilhouetteJob& job, int y, int x0, int x1) {
    return HWY_DYNAMIC_DISPATCH(Span)(job, y, x0, x1);
}
}  // namespace darkroom::passes
#endif
