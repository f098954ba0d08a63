// Half resolution: the estimator runs at the pixels with even x and even y
// (on the full-resolution depth, so no geometry is lost), and every other
// pixel takes the mean of its computed neighbours when all of them lie on its
// own surface: within one pixel footprint of its tangent plane, normals within
// about 25 degrees. A pixel next to a depth edge or a crease (or the image
// border, or a one-pixel feature) is computed itself, so occlusion neither
// bleeds across silhouettes (the halos of plain upsampling) nor is
// extrapolated from one side where it changes fastest.
//
//   even row:  computed  fill(L, R)  computed ...
//   odd row:   fill(U, D)  fill(4 diagonals)  ...
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "half_resolution.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include "half_resolution.h"
#include "simd-inl.h"

#include <hwy/highway.h>

#include <cmath>
#include <limits>

HWY_BEFORE_NAMESPACE();
namespace darkroom::ssao::HWY_NAMESPACE {

// Row y of `out` from the sparse results in `in`; the pixels that cannot be
// filled go to `missing` (their x), their count is returned.
int FillRow(const Frame& g, int y, const float* in, float* out, std::int32_t* missing) {
    const DF d;
    const DI di;
    const int N = int(hn::Lanes(d));
    const bool evenRow = y % 2 == 0;
    const std::size_t row = g.offset(0, y);
    const std::ptrdiff_t S = g.stride;
    const bool persp = g.perspective();
    const VF zero = hn::Zero(d), one = hn::Set(d, 1.0f), half = hn::Set(d, 0.5f);
    const VF inf = hn::Set(d, std::numeric_limits<float>::infinity());
    const VF ax = hn::Set(d, g.ax), bx = hn::Set(d, g.bx);
    auto rowY = [&](int r) { return hn::Set(d, g.ay * (float(r) + 0.5f) + g.by); };
    const VF syC = rowY(y), syU = rowY(y - 1), syD = rowY(y + 1);
    // Vectors start at even x, so lane parity is x parity.
    const MF oddX = hn::RebindMask(d, hn::Eq(hn::And(hn::Iota(di, 0), hn::Set(di, 1)), hn::Set(di, 1)));
    const MF evenX = hn::Not(oddX);
    auto position = [&](VF px, VF sy, VF z) {
        const VF sx = hn::MulAdd(px, ax, bx);
        return persp ? V3{hn::Mul(sx, z), hn::Mul(sy, z), z} : V3{sx, sy, z};
    };
    int count = 0;
    alignas(64) std::int32_t lanes[64];
    for (int x = 0; x < g.width(); x += N) {
        const std::size_t i = row + std::size_t(x);
        const VF zc = hn::Load(d, g.z + i);
        const MF valid = hn::Lt(zc, inf);
        // Computed pixels keep their value, background gets 1.
        const MF fill = hn::And(valid, evenRow ? oddX : hn::Not(hn::FirstN(d, 0)));
        VF result = hn::IfThenElse(valid, hn::Load(d, in + i), one);
        if (!hn::AllFalse(d, fill)) {
            const VF zs = hn::IfThenElse(valid, zc, one);
            const VF cx = hn::Add(hn::ConvertTo(d, hn::Add(hn::Iota(di, 0), hn::Set(di, x))), half);
            const V3 p = position(cx, syC, zs);
            const V3 nrm{hn::Load(d, g.n[0] + i), hn::Load(d, g.n[1] + i), hn::Load(d, g.n[2] + i)};
            // One pixel footprint at the pixel's depth.
            const VF tolerance = persp ? hn::Mul(hn::Set(d, g.pixelScale), zs) : hn::Set(d, g.pixelScale);
            const VF planeP = Dot(nrm, p);
            // Normals within about 25 degrees: across a crease occlusion changes
            // fastest (and reconstructed normals bend), so those pixels are computed.
            const VF minCos = hn::Set(d, 0.9f);
            VF sum = zero;
            MF filled = fill;  // until a neighbour is off the surface
            auto consider = [&](std::ptrdiff_t offset, float dx, VF sy, MF applies) {
                const VF zq = hn::LoadU(d, g.z + std::ptrdiff_t(i) + offset);
                const MF here = hn::And(fill, applies);
                const V3 q = position(hn::Add(cx, hn::Set(d, dx)), sy, hn::IfThenElse(hn::Lt(zq, inf), zq, one));
                const V3 nq{hn::LoadU(d, g.n[0] + std::ptrdiff_t(i) + offset), hn::LoadU(d, g.n[1] + std::ptrdiff_t(i) + offset),
                            hn::LoadU(d, g.n[2] + std::ptrdiff_t(i) + offset)};
                const MF ok = hn::And(hn::And(hn::Lt(zq, inf), hn::Le(hn::Abs(hn::Sub(Dot(nrm, q), planeP)), tolerance)),
                                      hn::Ge(Dot(nrm, nq), minCos));
                filled = hn::AndNot(hn::AndNot(ok, here), filled);
                sum = hn::Add(sum, hn::IfThenElseZero(here, hn::LoadU(d, in + std::ptrdiff_t(i) + offset)));
            };
            VF mean;
            if (evenRow) {
                consider(-1, -1.0f, syC, oddX);
                consider(1, 1.0f, syC, oddX);
                mean = hn::Mul(sum, half);
            } else {
                consider(-S, 0.0f, syU, evenX);
                consider(S, 0.0f, syD, evenX);
                consider(-S - 1, -1.0f, syU, oddX);
                consider(-S + 1, 1.0f, syU, oddX);
                consider(S - 1, -1.0f, syD, oddX);
                consider(S + 1, 1.0f, syD, oddX);
                mean = hn::Mul(sum, hn::IfThenElse(oddX, hn::Set(d, 0.25f), half));
            }
            result = hn::IfThenElse(filled, mean, result);
            const MF alone = hn::AndNot(filled, fill);
            if (!hn::AllFalse(d, alone)) {
                hn::Store(hn::IfThenElseZero(hn::RebindMask(di, alone), hn::Set(di, 1)), di, lanes);
                for (int k = 0; k < N && x + k < g.width(); ++k)
                    if (lanes[k]) missing[count++] = x + k;
            }
        }
        hn::Store(result, d, out + i);
    }
    return count;
}

}  // namespace darkroom::ssao::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace darkroom::ssao {

HWY_EXPORT(FillRow);

int fillRow(const Frame& g, int y, const float* sparse, float* out, std::int32_t* missing) {
    return HWY_DYNAMIC_DISPATCH(FillRow)(g, y, sparse, out, missing);
}

}  // namespace darkroom::ssao
#endif  // HWY_ONCE
