// Separable depth-aware blur, SIMD over the pixels of a row (Highway). Both
// passes read whole vectors (the horizontal taps are the row shifted by k,
// the vertical ones the row k above or below); the frame's padding reads as
// "no surface", so there are no bounds checks.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "bilateral_blur.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include "bilateral_blur.h"
#include "simd-inl.h"

#include <hwy/highway.h>

#include <cmath>
#include <limits>
#include <vector>

HWY_BEFORE_NAMESPACE();
namespace darkroom::ssao::HWY_NAMESPACE {

// The range weight exp(-x), x >= 0, as (1 - x/16)^16 (within 0.018 of it,
// exactly 0 beyond x = 16): an edge-stopping weight needs the Gaussian's
// shape, not its digits, and four squarings cost a fifth of hn::Exp, which
// was most of a tap.
HWY_INLINE VF RangeWeight(DF d, VF x) {
    const VF t = hn::Max(hn::NegMulAdd(x, hn::Set(d, 1.0f / 16.0f), hn::Set(d, 1.0f)), hn::Zero(d));
    const VF t2 = hn::Mul(t, t), t4 = hn::Mul(t2, t2), t8 = hn::Mul(t4, t4);
    return hn::Mul(t8, t8);
}

// One row of one pass: dst = blur of src along (dx, dy) = (1, 0) or (0, 1).
void BlurRow(const Frame& g, const AoSettings& s, const float* spatial, int radius, bool vertical, int y,
             const float* src, float* dst) {
    const DF d;
    const DI di;
    const int N = int(hn::Lanes(d));
    const bool persp = g.perspective();
    const std::size_t row = g.offset(0, y);
    const std::ptrdiff_t step = vertical ? std::ptrdiff_t(g.stride) : 1;
    const float* z = g.z;
    const VF zero = hn::Zero(d), half = hn::Set(d, 0.5f), one = hn::Set(d, 1.0f);
    const VF inf = hn::Set(d, std::numeric_limits<float>::infinity());
    const VF ax = hn::Set(d, g.ax), bx = hn::Set(d, g.bx);
    const VF sy = hn::Set(d, g.ay * (float(y) + 0.5f) + g.by);
    // sigma = 0.1 R: the range weight is exp(-plane^2 / sigma^2) (RangeWeight).
    const float radiusScale = 0.1f * (s.radiusInImageHeight ? s.radius * float(g.height()) : 1.0f);
    for (int x = 0; x < g.width(); x += N) {
        const std::size_t i = row + std::size_t(x);
        const VF zc = hn::Load(d, z + i);
        const VF centre = hn::Load(d, src + i);
        const MF valid = hn::Lt(zc, inf);
        if (hn::AllFalse(d, valid)) {
            hn::Store(centre, d, dst + i);
            continue;
        }
        const VF zs = hn::IfThenElse(valid, zc, one);
        const VF cx = hn::Add(hn::ConvertTo(d, hn::Add(hn::Iota(di, 0), hn::Set(di, x))), half);
        const VF sx = hn::MulAdd(cx, ax, bx);
        const V3 nrm{hn::Load(d, g.n[0] + i), hn::Load(d, g.n[1] + i), hn::Load(d, g.n[2] + i)};
        // Distance of a neighbour q from the centre's tangent plane:
        // n . (q - p). Perspective: q = (sx_q z_q, sy_q z_q, z_q).
        const VF planeP = Dot(nrm, persp ? V3{hn::Mul(sx, zs), hn::Mul(sy, zs), zs} : V3{sx, sy, zs});
        VF sigma = s.radiusInImageHeight
                       ? hn::Mul(hn::Set(d, radiusScale * g.pixelScale), persp ? zs : one)
                       : hn::Set(d, 0.1f * s.radius);
        const VF inv = hn::IfThenElseZero(hn::Gt(sigma, zero), hn::Div(one, hn::Mul(sigma, sigma)));
        VF sum = hn::Mul(hn::Set(d, spatial[0]), centre), weight = hn::Set(d, spatial[0]);
        for (int k = -radius; k <= radius; ++k) {
            if (k == 0) continue;
            const std::ptrdiff_t o = std::ptrdiff_t(k) * step;
            const VF zq = hn::LoadU(d, z + std::ptrdiff_t(i) + o);
            const MF ok = hn::And(valid, hn::Lt(zq, inf));
            if (hn::AllFalse(d, ok)) continue;
            VF qx = sx, qy = sy;
            if (vertical)
                qy = hn::Set(d, g.ay * (float(y + k) + 0.5f) + g.by);
            else
                qx = hn::MulAdd(hn::Add(cx, hn::Set(d, float(k))), ax, bx);
            const VF zqs = hn::IfThenElse(ok, zq, one);
            const V3 q = persp ? V3{hn::Mul(qx, zqs), hn::Mul(qy, zqs), zqs} : V3{qx, qy, zqs};
            const VF plane = hn::Sub(Dot(nrm, q), planeP);
            const VF w = hn::Mul(hn::Set(d, spatial[std::size_t(std::abs(k))]),
                                 RangeWeight(d, hn::Mul(hn::Mul(plane, plane), inv)));
            const VF wk = hn::IfThenElseZero(ok, w);
            sum = hn::MulAdd(wk, hn::LoadU(d, src + std::ptrdiff_t(i) + o), sum);
            weight = hn::Add(weight, wk);
        }
        hn::Store(hn::IfThenElse(valid, hn::Div(sum, weight), centre), d, dst + i);
    }
}

}  // namespace darkroom::ssao::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace darkroom::ssao {

HWY_EXPORT(BlurRow);

std::vector<float> blurWeights(int radius) {
    std::vector<float> spatial(std::size_t(radius) + 1);
    const float sigma = 0.5f * float(radius);
    for (int k = 0; k <= radius; ++k) spatial[std::size_t(k)] = std::exp(-0.5f * float(k * k) / (sigma * sigma));
    return spatial;
}

void blurRows(const Frame& g, const AoSettings& s, const std::vector<float>& spatial, bool vertical, int y0, int y1,
              const float* src, float* dst) {
    const int radius = int(spatial.size()) - 1;
    for (int y = y0; y < y1; ++y) HWY_DYNAMIC_DISPATCH(BlurRow)(g, s, spatial.data(), radius, vertical, y, src, dst);
}

}  // namespace darkroom::ssao
#endif  // HWY_ONCE
