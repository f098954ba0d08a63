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
// SIMD over the pixels of a row (one lane per pixel, Highway). A sample costs
// four gathered depths and about sixty vector operations, with no square
// root or division unless it falls in the falloff band: samples interpolate
// 1/z and are compared in a space scaled by it, and the running horizon is
// kept as a fraction of c|c|. Per slice, the directions are rotations of one
// sine/cosine pair, the normal's angle enters through its sine and cosine
// only, and a(h) is expanded with double-angle identities (one acos a side).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "horizon_ao.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include "ao_estimators.h"
#include "noise.h"
#include "simd-inl.h"

#include <hwy/contrib/math/math-inl.h>
#include <hwy/highway.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

HWY_BEFORE_NAMESPACE();
namespace darkroom::ssao::HWY_NAMESPACE {

// Per-pixel quantities of the receivers in one vector.
struct Receiver {
    VF fx, fy;        // pixel centre minus half a pixel (the bilinear lattice's origin)
    V3 p, v, origin;  // position, unit vector to the camera, origin lifted along the normal
    VF R, coreR, invFalloffR, stepScale, stepOffset;
    // Points geometry, perspective: an occluder's 1/z must lie in
    // (pointsMinF, pointsMaxF], i.e. z in [p.z - thickness, p.z).
    // Orthographic: z in [p.z - thickness, p.z).
    VF pointsMinF, pointsMaxF, thick;
};

// Constants of the sample loop, hoisted out of it.
struct Lattice {
    const float* f;
    const float* z;
    float stride;
    int base;         // plane offset of pixel (0, 0)
    bool smallPlane;  // every offset below 2^23
    bool canInterp;   // at least 2 x 2 pixels
    float maxX0, maxY0, edge, ax, ay, halfAx, halfAy;
    float indexBase;  // base + 2^23

    explicit Lattice(const Frame& g)
        : f(g.f), z(g.z), stride(float(g.stride)), base(int(g.offset(0, 0))),
          smallPlane(g.planeSize() < (std::size_t(1) << 23)), canInterp(g.width() >= 2 && g.height() >= 2),
          maxX0(float(g.width() - 2)), maxY0(float(g.height() - 2)), edge(4.0f * g.pixelScale), ax(g.ax), ay(g.ay),
          halfAx(g.bx + 0.5f * g.ax), halfAy(g.by + 0.5f * g.ay), indexBase(float(base) + 8388608.0f) {}

    // Plane offsets of pixels (x, y), given as integer-valued floats.
    HWY_INLINE VI Index(DF d, VF x, VF y) const {
        const DI di;
        if (smallPlane) {
            // Exact below 2^23: the integer is in the mantissa of at + 2^23.
            const VF at = hn::MulAdd(y, hn::Set(d, stride), hn::Add(x, hn::Set(d, indexBase)));
            return hn::Sub(hn::BitCast(di, at), hn::Set(di, 0x4b000000));
        }
        return hn::Add(hn::Add(hn::Mul(hn::ConvertTo(di, y), hn::Set(di, int(stride))), hn::ConvertTo(di, x)),
                       hn::Set(di, base));
    }
};

// The march along one side of one slice, towards its horizon: the highest
// cosine (from V) of the occluders met within the radius, starting from
// lowCos (the normal's hemisphere edge), blended towards lowCos by the
// falloff weight. The march stops at distance tExit (pixels), where the
// screen line leaves the image.
//
// The running maximum is kept as a fraction num/den of the monotone c|c|,
// so an occluder within (1 - falloff) R, whose weight is 1, is compared as
// dot|dot| * den > num * |d|^2 without a square root or a division; only the
// occluders in the falloff band need the distance itself.
struct March {
    MF live;
    VF dirX, dirY, tExit, lowCos, num, den;
};

HWY_INLINE March StartMarch(DF d, MF live, VF dirX, VF dirY, VF tExit, VF lowCos) {
    return {live, dirX, dirY, tExit, lowCos, hn::Mul(lowCos, hn::Abs(lowCos)), hn::Set(d, 1.0f)};
}

// The horizon cosine in [-1, 1]: c|c| = num / den.
HWY_INLINE VF Horizon(DF d, const March& m) {
    const VF mag = hn::Sqrt(hn::Div(hn::Abs(m.num), m.den));
    const VF best = hn::IfThenElse(hn::Lt(m.num, hn::Zero(d)), hn::Neg(mag), mag);
    return hn::Min(hn::Max(best, hn::Set(d, -1.0f)), hn::Set(d, 1.0f));
}

// Where sample `dist` of march m lands: its 1/z (perspective) or z, its
// image-plane position (at unit depth in perspective), whether it can
// occlude, and which lanes took the nearest pixel instead of interpolating.
struct Sample {
    VF fq, qx, qy;
    MF hit, nearest;
    bool anyNearest;
};

// The four pixels around a sample, x0 .. x0 + 1 and y0 .. y0 + 1, the
// sample at offsets (tx, ty) from the first: f interpolated between them and
// whether they are one surface (`ok`).
struct Texels {
    VF f00, f10, f01, f11, tx, ty, x0, y0, f;
    MF ok;

    // The pixel nearest the sample, the one floor(x + 1/2) reads (also where
    // the lattice is clamped at the border): its f and its coordinates. It
    // is one of the four already gathered, so an edge costs no fifth gather
    // (and no division: f holds 1/z, as exactly as dividing z here).
    HWY_INLINE VF Nearest(DF d, VF& nx, VF& ny) const {
        const VF half = hn::Set(d, 0.5f), one = hn::Set(d, 1.0f);
        const MF right = hn::Ge(tx, half), down = hn::Ge(ty, half);
        nx = hn::Add(x0, hn::IfThenElseZero(right, one));
        ny = hn::Add(y0, hn::IfThenElseZero(down, one));
        return hn::IfThenElse(down, hn::IfThenElse(right, f11, f01), hn::IfThenElse(right, f10, f00));
    }
};

// Depth at the samples (fx, fy) interpolated in 1/z (perspective) or z
// between the four surrounding pixel centres, exact on a plane; `ok` where
// they are one surface (spread within 4 pixel sizes, none empty).
template <bool kPersp>
HWY_INLINE Texels FineAt(DF d, const Lattice& L, VF fx, VF fy) {
    const VF zero = hn::Zero(d);
    const float* f = L.f;
    const std::size_t below = std::size_t(L.stride);
    // Clamped, so the outer half pixel at the borders is extrapolated
    // from the two outermost rows/columns (still exact for a plane);
    // the clamp also keeps every lane's reads inside the plane.
    const VF x0 = hn::Min(hn::Max(hn::Floor(fx), zero), hn::Set(d, L.maxX0));
    const VF y0 = hn::Min(hn::Max(hn::Floor(fy), zero), hn::Set(d, L.maxY0));
    const VF tx = hn::Sub(fx, x0), ty = hn::Sub(fy, y0);
    const VI idx = L.Index(d, x0, y0);
    const VF f00 = hn::GatherIndex(d, f, idx), f10 = hn::GatherIndex(d, f + 1, idx);
    const VF f01 = hn::GatherIndex(d, f + below, idx), f11 = hn::GatherIndex(d, f + below + 1, idx);
    const VF lo = hn::Min(hn::Min(f00, f10), hn::Min(f01, f11));
    const VF hi = hn::Max(hn::Max(f00, f10), hn::Max(f01, f11));
    // Perspective: z spread <= 4 pixel sizes at the nearest z, i.e.
    // (1/z) spread <= 4 * pixelScale * min(1/z). An empty corner
    // (-inf) fails either test.
    const VF edge = hn::Set(d, L.edge);
    const MF ok = hn::Le(hn::Sub(hi, lo), kPersp ? hn::Mul(edge, lo) : edge);
    const VF top = hn::MulAdd(hn::Sub(f10, f00), tx, f00);
    const VF bottom = hn::MulAdd(hn::Sub(f11, f01), tx, f01);
    return {f00, f10, f01, f11, tx, ty, x0, y0, hn::MulAdd(hn::Sub(bottom, top), ty, top), ok};
}

template <bool kPersp, bool kPoints>
HWY_INLINE Sample SampleAt(DF d, const Lattice& L, const Receiver& r, VF dist, const March& m) {
    const VF ax = hn::Set(d, L.ax), ay = hn::Set(d, L.ay), halfAx = hn::Set(d, L.halfAx), halfAy = hn::Set(d, L.halfAy);
    const VF ninf = hn::Set(d, -std::numeric_limits<float>::infinity());
    const MF live = m.live;
    // The sample in pixel coordinates minus half a pixel.
    const VF fx = hn::MulAdd(m.dirX, dist, r.fx), fy = hn::MulAdd(m.dirY, dist, r.fy);

    // fq: the sample's 1/z (perspective) or z, interpolated where the four
    // pixels around it are one surface, else the nearest pixel's (an edge
    // or an empty corner); (qx, qy): its image-plane position (at unit depth
    // in perspective), at the nearest pixel's centre for those.
    VF fq = hn::Zero(d), nx = fx, ny = fy;
    MF nearest = hn::FirstN(d, 0);
    if (L.canInterp) {
        const Texels t = FineAt<kPersp>(d, L, fx, fy);
        fq = t.f;
        nearest = hn::AndNot(t.ok, live);
        if (!hn::AllFalse(d, nearest)) {
            VF px, py;
            fq = hn::IfThenElse(nearest, t.Nearest(d, px, py), fq);
            nx = hn::IfThenElse(nearest, px, nx);
            ny = hn::IfThenElse(nearest, py, ny);
        }
    } else {
        // A single row or column: the nearest pixel. fx + 0.5 >= 0 for
        // marching lanes; the others read pixel 0.
        const VF half = hn::Set(d, 0.5f);
        nx = hn::Floor(hn::Add(fx, half)), ny = hn::Floor(hn::Add(fy, half));
        const VI idx = hn::IfThenElseZero(hn::RebindMask(DI(), live), L.Index(d, nx, ny));
        fq = hn::GatherIndex(d, L.f, idx);
        nearest = live;
    }
    const VF qx = hn::MulAdd(nx, ax, halfAx), qy = hn::MulAdd(ny, ay, halfAy);
    // Background (f = -inf) never occludes.
    MF hit = hn::AndNot(hn::AndNot(hn::Gt(fq, ninf), nearest), live);
    if (kPoints)
        hit = kPersp ? hn::And(hit, hn::And(hn::Gt(fq, r.pointsMinF), hn::Le(fq, r.pointsMaxF)))
                     : hn::And(hit, hn::And(hn::Lt(fq, r.p.z), hn::Le(hn::Sub(r.p.z, fq), r.thick)));
    return {fq, qx, qy, hit, nearest, !hn::AllFalse(d, nearest)};
}

// One sample of march m at `dist` pixels from the receiver.
template <bool kPersp, bool kPoints, bool kFalloff>
HWY_INLINE void Step(DF d, const Lattice& L, const Receiver& r, V3 axis, VF dist, March& m) {
    const VF zero = hn::Zero(d), one = hn::Set(d, 1.0f);
    const VF lowCos = m.lowCos;
    VF num = m.num, den = m.den;
    const auto [fq, qx, qy, hit, nearest, anyNearest] = SampleAt<kPersp, kPoints>(d, L, r, dist, m);
    // The sample minus the origin; in perspective scaled by the sample's
    // 1/z, which leaves the horizon cosine unchanged and saves a division:
    // (1/z) (q - o) = (qx - o.x / z, qy - o.y / z, 1 - o.z / z).
    V3 dd = kPersp ? V3{hn::NegMulAdd(r.origin.x, fq, qx), hn::NegMulAdd(r.origin.y, fq, qy),
                        hn::NegMulAdd(r.origin.z, fq, one)}
                   : V3{hn::Sub(qx, r.origin.x), hn::Sub(qy, r.origin.y), hn::Sub(fq, r.origin.z)};
    // Nearest-pixel samples need not lie in the slice: measured within
    // it. Interpolated ones lie on the slice's screen line, so in it.
    if (anyNearest) dd = Select(nearest, SubScaled(dd, axis, Dot(dd, axis)), dd);
    const VF len2 = Dot(dd, dd);
    const VF dotV = Dot(dd, r.v);
    // Radii in dd's units: R (orthographic) or R / z (perspective).
    const VF coreR = kPersp ? hn::Mul(r.coreR, fq) : r.coreR;
    // Full weight within the core (for a hard cut the radius, inclusive).
    // A zero-length |d| compares 0 > 0 and never wins.
    const MF full = hn::And(hit, kFalloff ? hn::Lt(len2, hn::Mul(coreR, coreR)) : hn::Le(len2, hn::Mul(coreR, coreR)));
    const VF candNum = hn::Mul(dotV, hn::Abs(dotV));
    const MF better = hn::And(full, hn::Gt(hn::Mul(candNum, den), hn::Mul(num, len2)));
    num = hn::IfThenElse(better, candNum, num);
    den = hn::IfThenElse(better, len2, den);
    if (kFalloff) {
        const VF radius = kPersp ? hn::Mul(r.R, fq) : r.R;
        const MF band = hn::AndNot(full, hn::And(hit, hn::Lt(len2, hn::Mul(radius, radius))));
        if (!hn::AllFalse(d, band)) {
            // Weight clamp((R - |q - o|) / (falloff R)), with |q - o| =
            // len z in perspective: 1/len and z both from 1/(len / z).
            const VF len = hn::Sqrt(len2);
            VF cosH, distance;
            if (kPersp) {
                const VF inv = hn::Div(one, hn::Mul(len, fq));
                cosH = hn::Mul(hn::Mul(dotV, fq), inv);
                distance = hn::Mul(len2, inv);
            } else {
                cosH = hn::Div(dotV, len);
                distance = len;
            }
            const VF w = hn::Min(hn::Max(hn::Mul(hn::Sub(r.R, distance), r.invFalloffR), zero), one);
            const VF c = hn::MulAdd(hn::Sub(cosH, lowCos), w, lowCos);
            const VF cNum = hn::Mul(c, hn::Abs(c));
            const MF wins = hn::And(band, hn::Gt(hn::Mul(cNum, den), num));
            num = hn::IfThenElse(wins, cNum, num);
            den = hn::IfThenElse(wins, one, den);
        }
    }
    m.num = num;
    m.den = den;
}

// Marches both sides of a slice together: they share the sample distances,
// and their two independent chains keep the pipeline fuller.
template <bool kPersp, bool kPoints, bool kFalloff>
HWY_INLINE void MarchSlice(DF d, const Lattice& L, int steps, const Receiver& r, V3 axis, March& plus, March& minus) {
    const VF one = hn::Set(d, 1.0f);
    for (int j = 0; j < steps; ++j) {
        const VF dist = hn::Max(one, hn::MulAdd(hn::Set(d, float(j)), r.stepScale, r.stepOffset));
        // Leaving the image ends a march (the screen line does not come back).
        plus.live = hn::And(plus.live, hn::Lt(dist, plus.tExit));
        minus.live = hn::And(minus.live, hn::Lt(dist, minus.tExit));
        const bool morePlus = !hn::AllFalse(d, plus.live), moreMinus = !hn::AllFalse(d, minus.live);
        if (!morePlus && !moreMinus) break;
        if (morePlus) Step<kPersp, kPoints, kFalloff>(d, L, r, axis, dist, plus);
        if (moreMinus) Step<kPersp, kPoints, kFalloff>(d, L, r, axis, dist, minus);
    }
}

// What every vector of a row shares.
struct HorizonConstants {
    Lattice lattice;
    int y;
    VF cy, sy;  // pixel centre y, and its image-plane y
    std::uint32_t rowHash, stream0, stream1;
    std::vector<float> rotCos, rotSin;  // rotation from the first slice to slice k

    HorizonConstants(DF d, const Frame& g, const AoSettings& s, int row)
        : lattice(g), y(row), cy(hn::Set(d, float(row) + 0.5f)), sy(hn::Set(d, g.ay * (float(row) + 0.5f) + g.by)),
          rowHash(mix32(std::uint32_t(row) + 0x632be5abU)), stream0(mix32(s.seed * 0x85ebca6bU + 0)),
          stream1(mix32(s.seed * 0x85ebca6bU + 1)), rotCos(std::size_t(s.slices)), rotSin(std::size_t(s.slices)) {
        for (int k = 0; k < s.slices; ++k) {
            rotCos[std::size_t(k)] = float(std::cos(double(k) * std::numbers::pi / s.slices));
            rotSin[std::size_t(k)] = float(std::sin(double(k) * std::numbers::pi / s.slices));
        }
    }
};

// The visibility integral of one slice, from its horizons' cosines (c2 on
// the + side, c1 on the - side) and the normal's angle g in the slice
// (cos g, sin g).
HWY_INLINE VF SliceIntegral(DF d, VF c1, VF c2, VF cosG, VF sinG) {
    const VF zero = hn::Zero(d), one = hn::Set(d, 1.0f);
    const VF quarter = hn::Set(d, 0.25f), two = hn::Set(d, 2.0f);
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
    return sum;
}

// Where a slice's screen line through (cx, cy) leaves the image, in
// pixels: the + side moves along (c, -sn), the - side along (-c, sn). A
// zero component gives an infinite reciprocal, signed as the zero was.
HWY_INLINE void SideExits(DF d, VF c, VF sn, VF cx, VF cy, VF toRight, VF toBottom, VF& exitPlus, VF& exitMinus) {
    const VF zero = hn::Zero(d), one = hn::Set(d, 1.0f);
    const VF invC = hn::Div(one, c), invS = hn::Div(one, sn);
    const VF a = hn::Mul(toRight, invC), b = hn::Mul(cx, invC);
    const VF cc = hn::Mul(toBottom, invS), dy = hn::Mul(cy, invS);
    const MF posC = hn::Gt(invC, zero), posS = hn::Gt(invS, zero);
    exitPlus = hn::Min(hn::IfThenElse(posC, a, hn::Neg(b)), hn::IfThenElse(posS, dy, hn::Neg(cc)));
    exitMinus = hn::Min(hn::IfThenElse(posC, b, hn::Neg(a)), hn::IfThenElse(posS, cc, hn::Neg(dy)));
}

// AO of the pixels (x, T.y) given by the lanes: centre cx = x + 0.5, x as
// an unsigned (for the noise), depth zc (+inf: none) and normal nrm.
template <bool kPersp, bool kPoints, bool kFalloff>
HWY_INLINE VF HorizonVector(DF d, const Frame& g, const AoSettings& s, const HorizonConstants& T, VF cx, VU xu, VF zc,
                            V3 nrm) {
    constexpr float kPi = std::numbers::pi_v<float>;
    const VF zero = hn::Zero(d), one = hn::Set(d, 1.0f), half = hn::Set(d, 0.5f);
    const VF inf = hn::Set(d, std::numeric_limits<float>::infinity());
    const VF W = hn::Set(d, float(g.width())), H = hn::Set(d, float(g.height()));
    const VF cy = T.cy, sy = T.sy;
    const VF invSlices = hn::Set(d, 1.0f / float(s.slices));
    const MF valid = hn::Lt(zc, inf);
    if (hn::AllFalse(d, valid)) return one;
    Receiver r;
    const VF zs = hn::IfThenElse(valid, zc, one);
    r.fx = hn::Sub(cx, half);
    r.fy = hn::Sub(cy, half);
    const VF sx = hn::MulAdd(cx, hn::Set(d, g.ax), hn::Set(d, g.bx));
    r.p = kPersp ? V3{hn::Mul(sx, zs), hn::Mul(sy, zs), zs} : V3{sx, sy, zs};
    r.v = kPersp ? Normalize(d, Scale(r.p, hn::Set(d, -1.0f))) : Splat(d, 0, 0, -1);
    const VF pixelSize = kPersp ? hn::Mul(hn::Set(d, g.pixelScale), zs) : hn::Set(d, g.pixelScale);
    r.R = s.radiusInImageHeight ? hn::Mul(hn::Set(d, s.radius * float(g.height())), pixelSize)
                                : hn::Set(d, s.radius);
    const VF radiusPixels = hn::Div(r.R, pixelSize);
    // Nothing is resolvable within a pixel; a radius beyond 1e30 pixels
    // puts every sample outside the image (and would overflow below).
    const MF active =
        hn::And(valid, hn::And(hn::Ge(radiusPixels, one), hn::Lt(radiusPixels, hn::Set(d, 1e30f))));
    if (hn::AllFalse(d, active)) return one;
    r.origin = AddScaled(r.p, nrm, hn::Mul(hn::Set(d, s.bias), r.R));
    r.thick = hn::Mul(hn::Set(d, s.thickness), r.R);
    if (kPoints && kPersp) {
        r.pointsMinF = hn::Div(one, zs);
        const VF back = hn::Sub(zs, r.thick);
        r.pointsMaxF = hn::IfThenElse(hn::Gt(back, zero), hn::Div(one, back), inf);
    }
    r.coreR = kFalloff ? hn::Mul(hn::Set(d, 1.0f - s.falloff), r.R) : r.R;
    r.invFalloffR = kFalloff ? hn::Div(one, hn::Mul(hn::Set(d, s.falloff), r.R)) : zero;
    VF sliceNoise = PixelNoise(d, xu, T.rowHash, T.stream0);
    if (s.interleave) sliceNoise = Stratify(d, xu, T.y, sliceNoise);
    const VF stepNoise = PixelNoise(d, xu, T.rowHash, T.stream1);
    // Sample j at max(1, (j + stepNoise) / steps * radiusPixels) pixels.
    r.stepScale = hn::IfThenElseZero(active, hn::Div(radiusPixels, hn::Set(d, float(s.steps))));
    r.stepOffset = hn::Mul(stepNoise, r.stepScale);

    // Basis of the plane perpendicular to V.
    const V3 e1 = Normalize(d, SubScaled(Splat(d, 1, 0, 0), r.v, r.v.x));
    const V3 e2 = Cross(r.v, e1);
    // Slices spread uniformly in angle around V (the integral's measure),
    // not around the screen axis: for off-centre pixels of a perspective
    // camera the two differ, and uniform screen angles bias AO by a few %.
    const VF phi0 = hn::Mul(sliceNoise, hn::Set(d, kPi / float(s.slices)));
    const VF cos0 = hn::Cos(d, phi0), sin0 = hn::Sin(d, phi0);
    // Distances to the image borders from the pixel centre.
    const VF toRight = hn::Sub(W, cx), toBottom = hn::Sub(H, cy);
    VF visibility = zero;
    for (int k = 0; k < s.slices; ++k) {
        const VF rc = hn::Set(d, T.rotCos[std::size_t(k)]), rs = hn::Set(d, T.rotSin[std::size_t(k)]);
        const VF cphi = hn::MulSub(cos0, rc, hn::Mul(sin0, rs));
        const VF sphi = hn::MulAdd(sin0, rc, hn::Mul(cos0, rs));
        const V3 orthoDir = Add(Scale(e1, cphi), Scale(e2, sphi));
        // The slice plane holds the camera ray, so it projects to a screen
        // line through the pixel, along d(X/Z, Y/Z).
        VF c = orthoDir.x, sn = orthoDir.y;
        if (kPersp) {
            c = hn::NegMulAdd(orthoDir.z, sx, c);
            sn = hn::NegMulAdd(orthoDir.z, sy, sn);
        }
        const VF screenLen = hn::Sqrt(hn::MulAdd(c, c, hn::Mul(sn, sn)));
        MF ok = hn::And(active, hn::Gt(screenLen, hn::Set(d, 1e-6f)));
        const VF invLen = hn::Div(one, screenLen);
        c = hn::Mul(c, invLen);
        sn = hn::Mul(sn, invLen);
        // The slice's normal: V and orthoDir are orthonormal.
        const V3 axis = Cross(orthoDir, r.v);
        const V3 projN = SubScaled(nrm, axis, Dot(nrm, axis));
        const VF projLen = hn::Sqrt(Dot(projN, projN));
        ok = hn::And(ok, hn::Gt(projLen, hn::Set(d, 1e-6f)));
        if (hn::AllFalse(d, ok)) continue;
        VF exitPlus, exitMinus;
        SideExits(d, c, sn, cx, cy, toRight, toBottom, exitPlus, exitMinus);
        // The normal's signed angle g in the slice, through its cosine and
        // sine (|g| <= pi/2: the normal faces the camera).
        const VF invP = hn::Div(one, projLen);
        const VF cosG = hn::Min(hn::Max(hn::Mul(Dot(projN, r.v), invP), hn::Set(d, -1.0f)), one);
        const VF sinG = hn::Mul(Dot(projN, orthoDir), invP);
        // Lowest horizons: the edges of the normal's hemisphere,
        // cos(g + pi/2) on the + side and cos(g - pi/2) on the - side.
        March plus = StartMarch(d, ok, c, hn::Neg(sn), exitPlus, hn::Neg(sinG));
        March minus = StartMarch(d, ok, hn::Neg(c), sn, exitMinus, sinG);
        MarchSlice<kPersp, kPoints, kFalloff>(d, T.lattice, s.steps, r, axis, plus, minus);
        const VF c2 = Horizon(d, plus), c1 = Horizon(d, minus);
        const VF sum = SliceIntegral(d, c1, c2, cosG, sinG);
        visibility = hn::Add(visibility, hn::IfThenElseZero(ok, hn::Mul(projLen, sum)));
    }
    const VF result = hn::Min(hn::Max(hn::Mul(visibility, invSlices), zero), one);
    return hn::IfThenElse(active, result, one);
}

template <bool kPersp, bool kPoints, bool kFalloff>
void HorizonRowT(const Frame& g, const AoSettings& s, int y, const std::int32_t* xs, int count, float* ao) {
    const DF d;
    const DI di;
    const DU du;
    const int N = int(hn::Lanes(d));
    const HorizonConstants T(d, g, s, y);
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
                result = HorizonVector<kPersp, kPoints, kFalloff>(d, g, s, T, hn::Add(hn::ConvertTo(d, xi), half),
                                                                  hn::BitCast(du, xi), zc, nrm);
            }
            hn::Store(result, d, ao + row + x);
        }
        return;
    }
    // The listed pixels: gathered, computed, scattered.
    alignas(64) std::int32_t lane[64];
    alignas(64) float out[64];
    for (int i = 0; i < count; i += N) {
        const int n = std::min(N, count - i);
        for (int k = 0; k < N; ++k) lane[k] = xs[i + std::min(k, n - 1)];
        const VI xi = hn::Load(di, lane);
        const VI at = hn::Add(xi, hn::Set(di, int(row)));
        const VF zc = hn::GatherIndex(d, g.z, at);
        const V3 nrm{hn::GatherIndex(d, g.n[0], at), hn::GatherIndex(d, g.n[1], at), hn::GatherIndex(d, g.n[2], at)};
        hn::Store(HorizonVector<kPersp, kPoints, kFalloff>(d, g, s, T, hn::Add(hn::ConvertTo(d, xi), half),
                                                            hn::BitCast(du, xi), zc, nrm),
                  d, out);
        for (int k = 0; k < n; ++k) ao[row + std::size_t(xs[i + k])] = out[k];
    }
}

// Row y: every pixel (xs null) or the count pixels xs.
void HorizonRow(const Frame& g, const AoSettings& s, int y, const std::int32_t* xs, int count, float* ao) {
    const bool points = s.geometry == Geometry::Points, falloff = s.falloff > 0;
    if (g.perspective()) {
        if (points)
            falloff ? HorizonRowT<true, true, true>(g, s, y, xs, count, ao)
                    : HorizonRowT<true, true, false>(g, s, y, xs, count, ao);
        else
            falloff ? HorizonRowT<true, false, true>(g, s, y, xs, count, ao)
                    : HorizonRowT<true, false, false>(g, s, y, xs, count, ao);
    } else {
        if (points)
            falloff ? HorizonRowT<false, true, true>(g, s, y, xs, count, ao)
                    : HorizonRowT<false, true, false>(g, s, y, xs, count, ao);
        else
            falloff ? HorizonRowT<false, false, true>(g, s, y, xs, count, ao)
                    : HorizonRowT<false, false, false>(g, s, y, xs, count, ao);
    }
}

}  // namespace darkroom::ssao::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace darkroom::ssao {

HWY_EXPORT(HorizonRow);

void horizonAO(const Frame& g, const AoSettings& s, int y0, int y1, float* ao) {
    for (int y = y0; y < y1; ++y) HWY_DYNAMIC_DISPATCH(HorizonRow)(g, s, y, nullptr, 0, ao);
}

void horizonAOAt(const Frame& g, const AoSettings& s, int y, const std::int32_t* xs, int count, float* ao) {
    if (count > 0) HWY_DYNAMIC_DISPATCH(HorizonRow)(g, s, y, xs, count, ao);
}

}  // namespace darkroom::ssao
#endif  // HWY_ONCE
