// normalAt (view_geometry.cpp) for a vector of pixels of a row at a time: the
// same double-precision operations in the same order, the branches of the
// per-pixel code turned into lane masks, so the bits match it.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/normals_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "normals_kernel.h"

#include <limits>

HWY_BEFORE_NAMESPACE();
namespace darkroom::normals {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using D = hn::ScalableTag<double>;
using DF = hn::Rebind<float, D>;
using V = hn::Vec<D>;
using M = hn::Mask<D>;

struct V3 {
    V x, y, z;
};

V3 sub(const V3& a, const V3& b) { return {hn::Sub(a.x, b.x), hn::Sub(a.y, b.y), hn::Sub(a.z, b.z)}; }
V3 select(M m, const V3& a, const V3& b) {
    return {hn::IfThenElse(m, a.x, b.x), hn::IfThenElse(m, a.y, b.y), hn::IfThenElse(m, a.z, b.z)};
}
V dot(const V3& a, const V3& b) { return hn::Add(hn::Add(hn::Mul(a.x, b.x), hn::Mul(a.y, b.y)), hn::Mul(a.z, b.z)); }
V3 scale(const V3& a, V s) { return {hn::Mul(a.x, s), hn::Mul(a.y, s), hn::Mul(a.z, s)}; }
// std::max / std::min as written: (a < b) ? b : a and (b < a) ? b : a.
V stdMax(V a, V b) { return hn::IfThenElse(hn::Lt(a, b), b, a); }
V stdMin(V a, V b) { return hn::IfThenElse(hn::Lt(b, a), b, a); }
M surface(V z) { return hn::Eq(hn::Sub(z, z), hn::Zero(D())); }

// One neighbour of the centre: its depth, whether it is usable, its position.
struct Sample {
    V z;
    M ok;
};

// The samples of one image axis and what chooseSide needs of them.
struct Axis {
    Sample l1, l2, r1, r2;
    V3 pl1, pr1;           // view positions of l1 and r1
    V al1, al2, ar1, ar2;  // affine depths (Extrapolated only)
};

// chooseSide and the tangent it selects (view_geometry.cpp), per lane.
V3 tangent(const Job& job, const Axis& s, V zc, V ac, const V3& pc, const V3& fallback) {
    const D d;
    const PlaneOffsets& g = *job.plane;
    const M l1 = s.l1.ok, r1 = s.r1.ok;
    const M onlyRight = hn::AndNot(l1, r1);
    const M onlyLeft = hn::AndNot(r1, l1);
    const M both = hn::And(l1, r1);
    M central = hn::FirstN(d, 0), left, nearerRule = both;
    if (job.method == NormalMethod::Central) {
        central = both;
        nearerRule = hn::FirstN(d, 0);
    } else if (job.method == NormalMethod::Extrapolated) {
        const M ext = hn::And(both, hn::And(s.l2.ok, s.r2.ok));
        const V two = hn::Set(d, 2.0);
        const V el = hn::Abs(hn::Sub(hn::Sub(hn::Mul(two, s.al1), s.al2), ac));
        const V er = hn::Abs(hn::Sub(hn::Sub(hn::Mul(two, s.ar1), s.ar2), ac));
        const V eps = hn::Mul(hn::Set(d, 1e-5), hn::Add(hn::Abs(ac), hn::Set(d, g.perspective ? 0.0 : g.pixelSize)));
        const M agree = hn::Le(stdMax(el, er), hn::Add(hn::Mul(two, stdMin(el, er)), eps));
        central = hn::And(ext, agree);
        left = hn::And(hn::AndNot(agree, ext), hn::Lt(el, er));
        nearerRule = hn::AndNot(ext, both);
    }
    const M nearerLeft = hn::Lt(hn::Abs(hn::Sub(s.l1.z, zc)), hn::Abs(hn::Sub(s.r1.z, zc)));
    const M fromRule = hn::And(nearerRule, nearerLeft);
    const M isLeft = job.method == NormalMethod::Extrapolated ? hn::Or(onlyLeft, hn::Or(left, fromRule))
                                                                : hn::Or(onlyLeft, fromRule);
    const M isRight = hn::Or(onlyRight, hn::AndNot(hn::Or(central, isLeft), both));
    V3 t = select(isRight, sub(s.pr1, pc), fallback);
    t = select(isLeft, sub(pc, s.pl1), t);
    return select(central, sub(s.pr1, s.pl1), t);
}

// The unit normal tx x ty turned towards the viewer; where the tangents
// give none (zero or NaN length), the direction to the viewer.
HWY_INLINE V3 orientedNormal(D d, const V3& tx, const V3& ty, const V3& toViewer) {
    const V zero = hn::Zero(d), one = hn::Set(d, 1.0);
    V3 n{hn::Sub(hn::Mul(tx.y, ty.z), hn::Mul(tx.z, ty.y)), hn::Sub(hn::Mul(tx.z, ty.x), hn::Mul(tx.x, ty.z)),
         hn::Sub(hn::Mul(tx.x, ty.y), hn::Mul(tx.y, ty.x))};
    const V len = hn::Sqrt(dot(n, n));
    const M usable = hn::And(hn::Gt(len, zero), surface(len));
    const V lv = hn::Sqrt(dot(toViewer, toViewer));
    const V3 viewerUnit = select(hn::Gt(lv, zero), scale(toViewer, hn::Div(one, lv)), toViewer);
    n = select(usable, scale(n, hn::Div(one, len)), viewerUnit);
    return select(hn::Lt(dot(n, toViewer), zero), V3{hn::Neg(n.x), hn::Neg(n.y), hn::Neg(n.z)}, n);
}

int Span(const Job& job, int y, int x0, int x1, const double* const affine[5]) {
    const D d;
    const DF df;
    const int lanes = int(hn::Lanes(d));
    const PlaneOffsets& g = *job.plane;
    const int w = job.width, h = job.height;
    const bool persp = g.perspective;
    const bool extrapolated = job.method == NormalMethod::Extrapolated;
    const NormalOutputs& out = job.out;
    const float* rows[5];
    M rowOk[5];
    double syOf[5];
    for (int k = 0; k < 5; ++k) {
        const int yy = y - 2 + k;
        const bool inside = yy >= 0 && yy < h;
        rows[k] = job.depth + std::size_t(inside ? yy : y) * std::size_t(w);
        rowOk[k] = hn::FirstN(d, inside ? std::size_t(lanes) : 0);
        syOf[k] = g.sy[std::size_t(inside ? yy : y)];
    }
    const V nanV = hn::Set(d, std::numeric_limits<double>::quiet_NaN());
    const V zSign = hn::Set(d, out.viewZTowardsViewer ? -1.0 : 1.0);
    const V zero = hn::Zero(d);
    const V one = hn::Set(d, 1.0);
    const V sy = hn::Set(d, syOf[2]);
    auto load = [&](int k, int x) { return hn::PromoteTo(d, hn::LoadU(df, rows[k] + x)); };
    auto sample = [&](int k, int x, M inside) {
        const V z = load(k, x);
        return Sample{z, hn::And(inside, surface(z))};
    };
    auto position = [&](V z, V sxv, V syv) {
        return persp ? V3{hn::Mul(z, sxv), hn::Mul(z, syv), z} : V3{sxv, syv, z};
    };
    auto affineAt = [&](int k, int x) { return affine[k] ? hn::LoadU(d, affine[k] + x) : zero; };
    auto store = [&](float* const* dst, std::size_t i, M valid, const V3& v) {
        const V c[3] = {v.x, v.y, v.z};
        for (int k = 0; k < 3; ++k)
            if (dst[k]) hn::StoreU(hn::DemoteTo(df, hn::IfThenElse(valid, c[k], nanV)), df, dst[k] + i);
    };
    const M all = hn::FirstN(d, std::size_t(lanes));
    const bool world = out.world[0] || out.world[1] || out.world[2];
    const bool positions = out.position[0] || out.position[1] || out.position[2];

    int x = x0;
    for (; x + lanes <= x1; x += lanes) {
        const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
        const V zc = load(2, x);
        const M valid = surface(zc);
        const V sxc = hn::LoadU(d, g.sx.data() + x);
        const V3 pc = position(zc, sxc, sy);
        const V ac = extrapolated ? affineAt(2, x) : zero;

        Axis ax;
        ax.l1 = sample(2, x - 1, all);
        ax.l2 = sample(2, x - 2, all);
        ax.r1 = sample(2, x + 1, all);
        ax.r2 = sample(2, x + 2, all);
        ax.pl1 = position(ax.l1.z, hn::LoadU(d, g.sx.data() + x - 1), sy);
        ax.pr1 = position(ax.r1.z, hn::LoadU(d, g.sx.data() + x + 1), sy);
        if (extrapolated) {
            ax.al1 = affineAt(2, x - 1);
            ax.al2 = affineAt(2, x - 2);
            ax.ar1 = affineAt(2, x + 1);
            ax.ar2 = affineAt(2, x + 2);
        }
        Axis ay;
        ay.l1 = sample(1, x, rowOk[1]);
        ay.l2 = sample(0, x, rowOk[0]);
        ay.r1 = sample(3, x, rowOk[3]);
        ay.r2 = sample(4, x, rowOk[4]);
        ay.pl1 = position(ay.l1.z, sxc, hn::Set(d, syOf[1]));
        ay.pr1 = position(ay.r1.z, sxc, hn::Set(d, syOf[3]));
        if (extrapolated) {
            ay.al1 = affineAt(1, x);
            ay.al2 = affineAt(0, x);
            ay.ar1 = affineAt(3, x);
            ay.ar2 = affineAt(4, x);
        }
        const V3 tx = tangent(job, ax, zc, ac, pc, V3{one, zero, zero});
        const V3 ty = tangent(job, ay, zc, ac, pc, V3{zero, hn::Neg(one), zero});  // image y runs down

        const V3 toViewer = persp ? V3{hn::Neg(pc.x), hn::Neg(pc.y), hn::Neg(pc.z)} : V3{zero, zero, hn::Neg(one)};
        const V3 n = orientedNormal(d, tx, ty, toViewer);

        store(out.view, i, valid, V3{n.x, n.y, hn::Mul(zSign, n.z)});
        const Vec3 basis[3] = {g.right, g.up, g.forward};
        auto toWorld = [&](const V3& v, int c) {
            return hn::Add(hn::Add(hn::Mul(hn::Set(d, basis[0][c]), v.x), hn::Mul(hn::Set(d, basis[1][c]), v.y)),
                           hn::Mul(hn::Set(d, basis[2][c]), v.z));
        };
        if (world) store(out.world, i, valid, V3{toWorld(n, 0), toWorld(n, 1), toWorld(n, 2)});
        if (positions)
            store(out.position, i, valid,
                  V3{hn::Add(hn::Set(d, g.origin.x), toWorld(pc, 0)), hn::Add(hn::Set(d, g.origin.y), toWorld(pc, 1)),
                     hn::Add(hn::Set(d, g.origin.z), toWorld(pc, 2))});
    }
    return x;
}

}  // namespace HWY_NAMESPACE
}  // namespace darkroom::normals
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace darkroom::normals {
HWY_EXPORT(Span);
int normalsSpan(const Job& job, int y, int x0, int x1, const double* const affine[5]) {
    return HWY_DYNAMIC_DISPATCH(Span)(job, y, x0, x1, affine);
}
}  // namespace darkroom::normals
#endif
