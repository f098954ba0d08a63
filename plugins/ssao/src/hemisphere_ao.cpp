// Classic normal-oriented hemisphere estimator (Crytek 2007 as reformulated
// around the normal by Bavoil and Sainz, "Screen Space Ambient Occlusion",
// NVIDIA 2008): points inside the hemisphere of radius R above the receiver
// are tested against the depth buffer; a point behind the visible surface is
// occluded, weighted by a range check on the occluder's distance.
//
// SIMD over the pixels of a row (one lane per pixel, Highway). The sample
// directions are one per-pixel rotation of a fixed spiral (tabulated sines
// and cosines), the distances a division-free cube root, so a sample costs a
// projection (one division) and one gathered depth.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "hemisphere_ao.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include "ao_estimators.h"
#include "noise.h"
#include "simd-inl.h"

#include <hwy/contrib/math/math-inl.h>
#include <hwy/highway.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

HWY_BEFORE_NAMESPACE();
namespace darkroom::ssao::HWY_NAMESPACE {

// What every vector of a row shares.
struct HemisphereConstants {
    int y;
    VF sy;  // image-plane y of the row's pixel centres
    std::uint32_t rowHash, stream0, stream1;
    // Cosine-distributed directions: a Vogel spiral on the unit disc lifted
    // to the hemisphere (Malley's method), rotated per pixel.
    std::vector<float> radial, lift, spinCos, spinSin;

    HemisphereConstants(DF d, const Frame& g, const AoSettings& s, int row)
        : y(row), sy(hn::Set(d, g.ay * (float(row) + 0.5f) + g.by)), rowHash(mix32(std::uint32_t(row) + 0x632be5abU)),
          stream0(mix32(s.seed * 0x85ebca6bU + 0)), stream1(mix32(s.seed * 0x85ebca6bU + 1)) {
        constexpr double kGoldenAngle = 2.39996322972865332;  // pi (3 - sqrt 5)
        const int n = s.samples;
        const std::size_t count = std::size_t(n);
        radial.resize(count), lift.resize(count), spinCos.resize(count), spinSin.resize(count);
        for (int k = 0; k < n; ++k) {
            const float r = std::sqrt((float(k) + 0.5f) / float(n));
            radial[std::size_t(k)] = r;
            lift[std::size_t(k)] = std::sqrt(std::max(0.0f, 1.0f - r * r));
            spinCos[std::size_t(k)] = float(std::cos(double(k) * kGoldenAngle));
            spinSin[std::size_t(k)] = float(std::sin(double(k) * kGoldenAngle));
        }
    }
};

// AO of the pixels (x, T.y) given by the lanes: centre cx = x + 0.5, x as
// an unsigned (for the noise), depth zc (+inf: none) and normal nrm.
HWY_INLINE VF HemisphereVector(DF d, const Frame& g, const AoSettings& s, const HemisphereConstants& T, VF cx, VU xu, VF zc,
                               V3 nrm) {
    const DI di;
    constexpr float kTwoPi = 6.28318530717958647692f;
    constexpr float kPlastic = 0.754877666246692760f;  // 1 / plastic number: a 1D low-discrepancy step
    const int n = s.samples;
    const bool persp = g.perspective(), points = s.geometry == Geometry::Points;
    const VF zero = hn::Zero(d), one = hn::Set(d, 1.0f);
    const VF inf = hn::Set(d, std::numeric_limits<float>::infinity());
    const VF W = hn::Set(d, float(g.width())), H = hn::Set(d, float(g.height()));
    const VI vStride = hn::Set(di, g.stride), vBase = hn::Set(di, int(g.offset(0, 0)));
    const VF sy = T.sy;
    // project(): px = (x/z / halfWidth + 1) W/2 = x/z * W/(2 halfWidth) + W/2.
    const VF projX = hn::Set(d, 0.5f * float(g.width()) / g.halfWidth()), offX = hn::Set(d, 0.5f * float(g.width()));
    const VF projY = hn::Set(d, -0.5f * float(g.height()) / g.halfHeight()), offY = hn::Set(d, 0.5f * float(g.height()));
    const MF valid = hn::Lt(zc, inf);
    if (hn::AllFalse(d, valid)) return one;
    const VF zs = hn::IfThenElse(valid, zc, one);
    const VF sx = hn::MulAdd(cx, hn::Set(d, g.ax), hn::Set(d, g.bx));
    const V3 p = persp ? V3{hn::Mul(sx, zs), hn::Mul(sy, zs), zs} : V3{sx, sy, zs};
    const VF pixelSize = persp ? hn::Mul(hn::Set(d, g.pixelScale), zs) : hn::Set(d, g.pixelScale);
    const VF R = s.radiusInImageHeight ? hn::Mul(hn::Set(d, s.radius * float(g.height())), pixelSize)
                                       : hn::Set(d, s.radius);
    // Tangent frame around the normal, rotated by a per-pixel angle.
    const MF useX = hn::Lt(hn::Abs(nrm.x), hn::Set(d, 0.9f));
    const V3 helper{hn::IfThenElseZero(useX, one), hn::IfThenZeroElse(useX, one), zero};
    const V3 t0 = Normalize(d, Cross(helper, nrm));
    const V3 b0 = Cross(nrm, t0);
    VF spin = PixelNoise(d, xu, T.rowHash, T.stream0);
    if (s.interleave) spin = Stratify(d, xu, T.y, spin);
    const VF jitter = PixelNoise(d, xu, T.rowHash, T.stream1);
    const VF rot = hn::Mul(hn::Set(d, kTwoPi), spin);
    const VF cosRot = hn::Cos(d, rot), sinRot = hn::Sin(d, rot);
    const V3 origin = AddScaled(p, nrm, hn::Mul(hn::Set(d, s.bias), R));
    const VF thick = hn::Mul(hn::Set(d, s.thickness), R);
    const VF invFalloffR = s.falloff > 0 ? hn::Div(one, hn::Mul(hn::Set(d, s.falloff), R)) : zero;
    VF occlusion = zero;
    for (int k = 0; k < n; ++k) {
        const VF sc = hn::Set(d, T.spinCos[std::size_t(k)]), ss = hn::Set(d, T.spinSin[std::size_t(k)]);
        const VF r = hn::Set(d, T.radial[std::size_t(k)]);
        const VF ca = hn::Mul(r, hn::MulSub(cosRot, sc, hn::Mul(sinRot, ss)));
        const VF sa = hn::Mul(r, hn::MulAdd(sinRot, sc, hn::Mul(cosRot, ss)));
        const V3 dir = AddScaled(AddScaled(Scale(nrm, hn::Set(d, T.lift[std::size_t(k)])), t0, ca), b0, sa);
        // Distances uniform in the volume of the ball (as Crytek's points
        // in a sphere). Against a solid occluder hit at distance t along
        // the ray this counts 1 - (t/R)^3 instead of ray-traced AO's 1:
        // the closest a single-point test gets (the popular
        // lerp(0.1, 1, u^2) gives 1 - sqrt((t/R - 0.1) / 0.9), far less
        // occlusion).
        VF u = hn::Add(jitter, hn::Set(d, float(k) * kPlastic));
        u = hn::Sub(u, hn::Floor(u));
        const VF dist = hn::Mul(R, CubeRoot(d, hn::MulAdd(u, hn::Set(d, 0.98f), hn::Set(d, 0.02f))));
        const V3 q = AddScaled(origin, dir, dist);
        MF inFront = valid;
        VF qx = q.x, qy = q.y;
        if (persp) {
            inFront = hn::And(inFront, hn::Gt(q.z, zero));
            const VF iz = hn::Div(one, q.z);
            qx = hn::Mul(qx, iz);
            qy = hn::Mul(qy, iz);
        }
        const VF px = hn::MulAdd(qx, projX, offX), py = hn::MulAdd(qy, projY, offY);
        const MF inside = hn::And(inFront, hn::And(hn::And(hn::Ge(px, zero), hn::Ge(py, zero)),
                                                   hn::And(hn::Lt(px, W), hn::Lt(py, H))));
        if (hn::AllFalse(d, inside)) continue;
        const VI idx = hn::IfThenElseZero(
            hn::RebindMask(di, inside),
            hn::Add(hn::Add(hn::Mul(hn::ConvertTo(di, py), vStride), hn::ConvertTo(di, px)), vBase));
        const VF occZ = hn::GatherIndex(d, g.z, idx);
        // Background (+inf) never occludes; the sample must lie behind the surface.
        MF occluded = hn::And(inside, hn::Gt(q.z, occZ));
        if (points)
            occluded = hn::And(occluded, hn::And(hn::And(hn::Lt(occZ, p.z), hn::Le(hn::Sub(p.z, occZ), thick)),
                                                 hn::Le(q.z, hn::Add(occZ, thick))));
        const VF dz = hn::Abs(hn::Sub(p.z, occZ));
        const VF w = s.falloff > 0 ? hn::Min(hn::Max(hn::Mul(hn::Sub(R, dz), invFalloffR), zero), one)
                                   : hn::IfThenElseZero(hn::Le(dz, R), one);
        occlusion = hn::Add(occlusion, hn::IfThenElseZero(occluded, w));
    }
    const VF result = hn::Min(hn::Max(hn::NegMulAdd(occlusion, hn::Set(d, 1.0f / float(n)), one), zero), one);
    return hn::IfThenElse(valid, result, one);
}

// Row y: every pixel (xs null) or the count pixels xs.
void HemisphereRow(const Frame& g, const AoSettings& s, int y, const std::int32_t* xs, int count, float* ao) {
    const DF d;
    const DI di;
    const DU du;
    const int N = int(hn::Lanes(d));
    const HemisphereConstants T(d, g, s, y);
    const std::size_t row = g.offset(0, y);
    const VF half = hn::Set(d, 0.5f), one = hn::Set(d, 1.0f);
    if (!xs) {
        // Every pixel of the row: whole vectors (the row's tail is padding).
        for (int x = 0; x < g.width(); x += N) {
            const VF zc = hn::Load(d, g.z + row + x);
            VF result = one;
            if (!hn::AllFalse(d, hn::Lt(zc, hn::Set(d, std::numeric_limits<float>::infinity())))) {
                const VI xi = hn::Add(hn::Iota(di, 0), hn::Set(di, x));
                const V3 nrm{hn::Load(d, g.n[0] + row + x), hn::Load(d, g.n[1] + row + x), hn::Load(d, g.n[2] + row + x)};
                result = HemisphereVector(d, g, s, T, hn::Add(hn::ConvertTo(d, xi), half), hn::BitCast(du, xi), zc, nrm);
            }
            hn::Store(result, d, ao + row + x);
        }
        return;
    }
    // The listed pixels: gathered, computed, scattered.
    alignas(64) std::int32_t lane[64];
    alignas(64) float out[64];
    for (int i = 0; i < count; i += N) {
        const int m = std::min(N, count - i);
        for (int k = 0; k < N; ++k) lane[k] = xs[i + std::min(k, m - 1)];
        const VI xi = hn::Load(di, lane);
        const VI at = hn::Add(xi, hn::Set(di, int(row)));
        const VF zc = hn::GatherIndex(d, g.z, at);
        const V3 nrm{hn::GatherIndex(d, g.n[0], at), hn::GatherIndex(d, g.n[1], at), hn::GatherIndex(d, g.n[2], at)};
        hn::Store(HemisphereVector(d, g, s, T, hn::Add(hn::ConvertTo(d, xi), half), hn::BitCast(du, xi), zc, nrm), d,
                  out);
        for (int k = 0; k < m; ++k) ao[row + std::size_t(xs[i + k])] = out[k];
    }
}

}  // namespace darkroom::ssao::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace darkroom::ssao {

HWY_EXPORT(HemisphereRow);

void hemisphereAO(const Frame& g, const AoSettings& s, int y0, int y1, float* ao) {
    for (int y = y0; y < y1; ++y) HWY_DYNAMIC_DISPATCH(HemisphereRow)(g, s, y, nullptr, 0, ao);
}

void hemisphereAOAt(const Frame& g, const AoSettings& s, int y, const std::int32_t* xs, int count, float* ao) {
    if (count > 0) HWY_DYNAMIC_DISPATCH(HemisphereRow)(g, s, y, xs, count, ao);
}

}  // namespace darkroom::ssao
#endif  // HWY_ONCE
