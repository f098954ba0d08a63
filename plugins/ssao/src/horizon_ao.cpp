// Horizon-based cosine-weighted AO after Jimenez et al. 2016, "Practical
// Realtime Strategies for Accurate Indirect Occlusion" (GTAO). The hemisphere
// is cut into `slices` planes containing the view vector V; in each, the two
// horizon angles h1 <= 0 <= h2 (from V) are found by marching `steps` depth
// samples per side in screen space, and the cosine-weighted visible fraction
// between them is integrated analytically:
//   AO = 1/slices * sum  |n_p| * (a(h1) + a(h2)),
//   a(h) = 1/4 (-cos(2h - g) + cos g + 2 h sin g),
// where n_p is the normal projected into the slice and g its signed angle
// from V. Weighting by |n_p| makes the slice average the exact cosine-weighted
// integral (1 for an unoccluded surface of any orientation).
//
// SIMD over the pixels of a row (one lane per pixel, Highway). Per sample the
// only transcendental work is one square root and two divisions: the slice
// directions are rotations of one sine/cosine pair, the normal's angle enters
// through its sine and cosine only, and a(h) is expanded with double-angle
// identities so that each side needs one acos.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "horizon_ao.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include "ao_estimators.h"
#include "noise.h"
#include "simd-inl.h"

#include <hwy/contrib/math/math-inl.h>
#include <hwy/highway.h>

#include <cmath>
#include <limits>
#include <vector>

HWY_BEFORE_NAMESPACE();
namespace darkroom::ssao::HWY_NAMESPACE {

struct SliceTable {
    std::vector<float> cos, sin;  // rotation from the first slice to slice k
};

// The horizon of one side of one slice: the highest cosine (from V) of the
// occluders met within the radius, starting from lowCos (the normal's
// hemisphere edge), blended towards lowCos by the falloff weight.
struct Receiver {
    VF cx, cy;           // pixel centre
    V3 p, v, origin;     // position, unit vector to the camera, lifted origin
    VF R, invFalloffR, thick, stepScale, stepOffset;
};

HWY_INLINE VF SideHorizon(DF d, const Frame& g, const AoSettings& s, const Receiver& r, MF live, VF dirX, VF dirY,
                          V3 axis, VF lowCos) {
    const DI di;
    const bool persp = g.perspective(), points = s.geometry == Geometry::Points;
    const bool canInterp = g.width() >= 2 && g.height() >= 2;
    const float* f = g.f.get();
    const float* z = g.z.get();
    const int base = int(g.offset(0, 0));
    const VI vStride = hn::Set(di, g.stride), vBase = hn::Set(di, base);
    const VF zero = hn::Zero(d), one = hn::Set(d, 1.0f), half = hn::Set(d, 0.5f);
    const VF W = hn::Set(d, float(g.width())), H = hn::Set(d, float(g.height()));
    const VF maxX0 = hn::Set(d, float(g.width() - 2)), maxY0 = hn::Set(d, float(g.height() - 2));
    const VF edge = hn::Set(d, 4.0f * g.pixelScale);
    const VF ax = hn::Set(d, g.ax), bx = hn::Set(d, g.bx), ay = hn::Set(d, g.ay), by = hn::Set(d, g.by);
    const VF inf = hn::Set(d, std::numeric_limits<float>::infinity());
    VF best = lowCos;
    for (int j = 0; j < s.steps; ++j) {
        const VF dist = hn::Max(one, hn::MulAdd(hn::Set(d, float(j)), r.stepScale, r.stepOffset));
        const VF sx = hn::MulAdd(dirX, dist, r.cx), sy = hn::MulAdd(dirY, dist, r.cy);
        // Leaving the image ends the march (the screen line does not come back).
        live = hn::And(live, hn::And(hn::And(hn::Ge(sx, zero), hn::Ge(sy, zero)), hn::And(hn::Lt(sx, W), hn::Lt(sy, H))));
        if (hn::AllFalse(d, live)) break;
        const auto liveI = hn::RebindMask(di, live);

        // Depth interpolated in 1/z (perspective) or z between the four
        // surrounding pixel centres, exact on a plane; the nearest pixel where
        // they straddle an edge (spread beyond 4 pixel sizes) or one is empty.
        VF zq = zero, qx = sx, qy = sy;
        MF interp = hn::FirstN(d, 0);
        if (canInterp) {
            const VF fx = hn::Sub(sx, half), fy = hn::Sub(sy, half);
            const VF x0 = hn::Min(hn::Max(hn::Floor(fx), zero), maxX0);
            const VF y0 = hn::Min(hn::Max(hn::Floor(fy), zero), maxY0);
            const VF tx = hn::Sub(fx, x0), ty = hn::Sub(fy, y0);
            const VI idx = hn::IfThenElseZero(
                liveI, hn::Add(hn::Add(hn::Mul(hn::ConvertTo(di, y0), vStride), hn::ConvertTo(di, x0)), vBase));
            const VF f00 = hn::GatherIndex(d, f, idx), f10 = hn::GatherIndex(d, f + 1, idx);
            const VF f01 = hn::GatherIndex(d, f + g.stride, idx), f11 = hn::GatherIndex(d, f + g.stride + 1, idx);
            const VF lo = hn::Min(hn::Min(f00, f10), hn::Min(f01, f11));
            const VF hi = hn::Max(hn::Max(f00, f10), hn::Max(f01, f11));
            // Perspective: z spread <= 4 pixel sizes at the nearest z, i.e.
            // (1/z) spread <= 4 * pixelScale * min(1/z). An empty corner
            // (-inf) fails either test.
            interp = hn::Le(hn::Sub(hi, lo), persp ? hn::Mul(edge, lo) : edge);
            const VF top = hn::MulAdd(hn::Sub(f10, f00), tx, f00);
            const VF bottom = hn::MulAdd(hn::Sub(f11, f01), tx, f01);
            const VF fv = hn::MulAdd(hn::Sub(bottom, top), ty, top);
            zq = persp ? hn::Div(one, fv) : fv;
        }
        MF hit = live;
        const MF nearest = hn::AndNot(interp, live);
        if (!hn::AllFalse(d, nearest)) {
            const VF nx = hn::Floor(sx), ny = hn::Floor(sy);
            const VI idx = hn::IfThenElseZero(
                liveI, hn::Add(hn::Add(hn::Mul(hn::ConvertTo(di, ny), vStride), hn::ConvertTo(di, nx)), vBase));
            const VF zn = hn::GatherIndex(d, z, idx);
            zq = hn::IfThenElse(nearest, zn, zq);
            qx = hn::IfThenElse(nearest, hn::Add(nx, half), qx);
            qy = hn::IfThenElse(nearest, hn::Add(ny, half), qy);
            // Background never occludes.
            hit = hn::AndNot(hn::AndNot(hn::Lt(zn, inf), nearest), hit);
        }
        const VF qsx = hn::MulAdd(qx, ax, bx), qsy = hn::MulAdd(qy, ay, by);
        const V3 sp = persp ? V3{hn::Mul(qsx, zq), hn::Mul(qsy, zq), zq} : V3{qsx, qsy, zq};
        if (points) hit = hn::And(hit, hn::And(hn::Lt(sp.z, r.p.z), hn::Le(hn::Sub(r.p.z, sp.z), r.thick)));
        // Measured within the slice (a no-op for interpolated samples, which
        // lie on it; nearest-pixel ones may not).
        V3 dd = Sub(sp, r.origin);
        dd = SubScaled(dd, axis, Dot(dd, axis));
        const VF len2 = Dot(dd, dd);
        hit = hn::And(hit, hn::Gt(len2, zero));
        if (hn::AllFalse(d, hit)) continue;
        const VF len = hn::Sqrt(len2);
        const VF w = s.falloff > 0 ? hn::Min(hn::Max(hn::Mul(hn::Sub(r.R, len), r.invFalloffR), zero), one)
                                   : hn::IfThenElseZero(hn::Le(len, r.R), one);
        const VF cosH = hn::Div(Dot(dd, r.v), len);
        const VF candidate = hn::MulAdd(hn::Sub(cosH, lowCos), w, lowCos);
        best = hn::IfThenElse(hit, hn::Max(best, candidate), best);
    }
    return hn::Min(hn::Max(best, hn::Set(d, -1.0f)), one);
}

void HorizonRow(const Frame& g, const AoSettings& s, int y, float* ao) {
    const DF d;
    const DI di;
    const int N = int(hn::Lanes(d));
    constexpr float kPi = 3.14159265358979323846f;
    const bool persp = g.perspective();
    const std::size_t row = g.offset(0, y);
    const VF zero = hn::Zero(d), one = hn::Set(d, 1.0f), half = hn::Set(d, 0.5f);
    const VF inf = hn::Set(d, std::numeric_limits<float>::infinity());
    const VF cy = hn::Set(d, float(y) + 0.5f);
    const VF sy = hn::Set(d, g.ay * (float(y) + 0.5f) + g.by);
    const std::uint32_t rowHash = mix32(std::uint32_t(y) + 0x632be5abU);
    const std::uint32_t stream0 = mix32(s.seed * 0x85ebca6bU + 0), stream1 = mix32(s.seed * 0x85ebca6bU + 1);
    const std::size_t sliceCount = std::size_t(s.slices);
    std::vector<float> rotCos(sliceCount), rotSin(sliceCount);
    for (int k = 0; k < s.slices; ++k) {
        rotCos[std::size_t(k)] = float(std::cos(double(k) * M_PI / s.slices));
        rotSin[std::size_t(k)] = float(std::sin(double(k) * M_PI / s.slices));
    }
    const VF invSlices = hn::Set(d, 1.0f / float(s.slices));
    const VF quarter = hn::Set(d, 0.25f), two = hn::Set(d, 2.0f);
    for (int x = 0; x < g.width(); x += N) {
        float* out = ao + row + std::size_t(x);
        const VF zc = hn::Load(d, g.z.get() + row + x);
        const MF valid = hn::Lt(zc, inf);
        if (hn::AllFalse(d, valid)) {
            hn::Store(one, d, out);
            continue;
        }
        Receiver r;
        const VF zs = hn::IfThenElse(valid, zc, one);
        const V3 nrm{hn::Load(d, g.n[0].get() + row + x), hn::Load(d, g.n[1].get() + row + x),
                     hn::Load(d, g.n[2].get() + row + x)};
        r.cx = hn::Add(hn::ConvertTo(d, hn::Add(hn::Iota(di, 0), hn::Set(di, x))), half);
        r.cy = cy;
        const VF sx = hn::MulAdd(r.cx, hn::Set(d, g.ax), hn::Set(d, g.bx));
        r.p = persp ? V3{hn::Mul(sx, zs), hn::Mul(sy, zs), zs} : V3{sx, sy, zs};
        r.v = persp ? Normalize(d, Scale(r.p, hn::Set(d, -1.0f))) : Splat(d, 0, 0, -1);
        const VF pixelSize = persp ? hn::Mul(hn::Set(d, g.pixelScale), zs) : hn::Set(d, g.pixelScale);
        r.R = s.radiusInImageHeight ? hn::Mul(hn::Set(d, s.radius * float(g.height())), pixelSize)
                                    : hn::Set(d, s.radius);
        const VF radiusPixels = hn::Div(r.R, pixelSize);
        // Nothing is resolvable within a pixel.
        const MF active = hn::And(valid, hn::Ge(radiusPixels, one));
        if (hn::AllFalse(d, active)) {
            hn::Store(one, d, out);
            continue;
        }
        r.origin = AddScaled(r.p, nrm, hn::Mul(hn::Set(d, s.bias), r.R));
        r.thick = hn::Mul(hn::Set(d, s.thickness), r.R);
        r.invFalloffR = s.falloff > 0 ? hn::Div(one, hn::Mul(hn::Set(d, s.falloff), r.R)) : zero;
        const VF sliceNoise = PixelNoise(d, x, rowHash, stream0);
        const VF stepNoise = PixelNoise(d, x, rowHash, stream1);
        // Sample j at max(1, (j + stepNoise) / steps * radiusPixels) pixels.
        r.stepScale = hn::Div(radiusPixels, hn::Set(d, float(s.steps)));
        r.stepOffset = hn::Mul(stepNoise, r.stepScale);

        // Basis of the plane perpendicular to V.
        const V3 e1 = Normalize(d, SubScaled(Splat(d, 1, 0, 0), r.v, r.v.x));
        const V3 e2 = Cross(r.v, e1);
        // Slices spread uniformly in angle around V (the integral's measure),
        // not around the screen axis: for off-centre pixels of a perspective
        // camera the two differ, and uniform screen angles bias AO by a few %.
        const VF phi0 = hn::Mul(sliceNoise, hn::Set(d, kPi / float(s.slices)));
        const VF cos0 = hn::Cos(d, phi0), sin0 = hn::Sin(d, phi0);
        VF visibility = zero;
        for (int k = 0; k < s.slices; ++k) {
            const VF rc = hn::Set(d, rotCos[std::size_t(k)]), rs = hn::Set(d, rotSin[std::size_t(k)]);
            const VF cphi = hn::MulSub(cos0, rc, hn::Mul(sin0, rs));
            const VF sphi = hn::MulAdd(sin0, rc, hn::Mul(cos0, rs));
            const V3 orthoDir = Add(Scale(e1, cphi), Scale(e2, sphi));
            // The slice plane holds the camera ray, so it projects to a screen
            // line through the pixel, along d(X/Z, Y/Z).
            VF c = orthoDir.x, sn = orthoDir.y;
            if (persp) {
                c = hn::NegMulAdd(orthoDir.z, sx, c);
                sn = hn::NegMulAdd(orthoDir.z, sy, sn);
            }
            const VF screenLen = hn::Sqrt(hn::MulAdd(c, c, hn::Mul(sn, sn)));
            MF ok = hn::And(active, hn::Gt(screenLen, hn::Set(d, 1e-6f)));
            const VF invLen = hn::Div(one, screenLen);
            c = hn::Mul(c, invLen);
            sn = hn::Mul(sn, invLen);
            const V3 axis = Normalize(d, Cross(orthoDir, r.v));
            const V3 projN = SubScaled(nrm, axis, Dot(nrm, axis));
            const VF projLen = hn::Sqrt(Dot(projN, projN));
            ok = hn::And(ok, hn::Gt(projLen, hn::Set(d, 1e-6f)));
            if (hn::AllFalse(d, ok)) continue;
            // The normal's signed angle g in the slice, through its cosine and
            // sine (|g| <= pi/2: the normal faces the camera).
            const VF invP = hn::Div(one, projLen);
            const VF cosG = hn::Min(hn::Max(hn::Mul(Dot(projN, r.v), invP), hn::Set(d, -1.0f)), one);
            const VF sinG = hn::Mul(Dot(projN, orthoDir), invP);
            // Lowest horizons: the edges of the normal's hemisphere,
            // cos(g + pi/2) on the + side and cos(g - pi/2) on the - side.
            const VF c2 = SideHorizon(d, g, s, r, ok, c, hn::Neg(sn), axis, hn::Neg(sinG));
            const VF c1 = SideHorizon(d, g, s, r, ok, hn::Neg(c), sn, axis, sinG);
            // h2 = acos(c2) in [0, pi], h1 = -acos(c1) in [-pi, 0]; both lie
            // within pi/2 of g because the march starts at the hemisphere edge.
            // a(h) with cos(2h - g) = cos 2h cos g + sin 2h sin g.
            const VF h2 = hn::Acos(d, c2), h1 = hn::Neg(hn::Acos(d, c1));
            const VF s2 = hn::Sqrt(hn::Max(hn::NegMulAdd(c2, c2, one), zero));
            const VF s1 = hn::Neg(hn::Sqrt(hn::Max(hn::NegMulAdd(c1, c1, one), zero)));
            const VF cos2h2 = hn::MulSub(two, hn::Mul(c2, c2), one), sin2h2 = hn::Mul(two, hn::Mul(s2, c2));
            const VF cos2h1 = hn::MulSub(two, hn::Mul(c1, c1), one), sin2h1 = hn::Mul(two, hn::Mul(s1, c1));
            const VF cosTerms = hn::Sub(two, hn::Add(cos2h2, cos2h1));
            const VF sinTerms = hn::Sub(hn::Mul(two, hn::Add(h2, h1)), hn::Add(sin2h2, sin2h1));
            const VF sum = hn::Mul(quarter, hn::MulAdd(sinTerms, sinG, hn::Mul(cosTerms, cosG)));
            visibility = hn::Add(visibility, hn::IfThenElseZero(ok, hn::Mul(projLen, sum)));
        }
        const VF result = hn::Min(hn::Max(hn::Mul(visibility, invSlices), zero), one);
        hn::Store(hn::IfThenElse(active, result, one), d, out);
    }
}

}  // namespace darkroom::ssao::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace darkroom::ssao {

HWY_EXPORT(HorizonRow);

void horizonAO(const Frame& g, const AoSettings& s, int y0, int y1, float* ao) {
    for (int y = y0; y < y1; ++y) HWY_DYNAMIC_DISPATCH(HorizonRow)(g, s, y, ao);
}

}  // namespace darkroom::ssao
#endif  // HWY_ONCE
