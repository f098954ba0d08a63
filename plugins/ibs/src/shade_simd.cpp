// shadeAt (shade.cpp) for a vector of pixels of a row at a time: the same
// double-precision operations in the same order, so the bits match it.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/shade_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "shade.h"

HWY_BEFORE_NAMESPACE();
namespace darkroom::passes {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using D = hn::ScalableTag<double>;
using DF = hn::Rebind<float, D>;
using V = hn::Vec<D>;

int Row(const ShadeJob& job, int y) {
    const D d;
    const DF df;
    const int lanes = int(hn::Lanes(d));
    const int w = job.width;
    if (w < lanes) return 0;
    const V zero = hn::Zero(d), one = hn::Set(d, 1.0);
    auto load = [&](const float* p) { return hn::PromoteTo(d, hn::LoadU(df, p)); };
    auto toFloat = [&](V v) { return hn::PromoteTo(d, hn::DemoteTo(df, v)); };
    const V ambient = hn::Set(d, job.ambient), diffuse = hn::Set(d, 1.0 - job.ambient);
    const V luminance = hn::Set(d, job.luminance);
    const V strength = hn::Set(d, job.strength * double(job.color.a));
    const V colour[3] = {hn::Set(d, job.color.r), hn::Set(d, job.color.g), hn::Set(d, job.color.b)};
    const double sy = job.sy.empty() ? 0.0 : job.sy[std::size_t(y)];
    for (int x = 0;; x += lanes) {
        // The last vector ends at the row's end, overlapping the one before
        // (pixels are independent: the overlap is computed twice alike).
        if (x + lanes > w) x = w - lanes;
        const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
        V v[3] = {load(job.rgb[0] + i), load(job.rgb[1] + i), load(job.rgb[2] + i)};
        if (job.lighting()) {
            V nv[3];
            if (job.worldNormals) {
                const V n[3] = {load(job.normal[0] + i), load(job.normal[1] + i), load(job.normal[2] + i)};
                const Vec3 basis[3] = {job.right, job.up, job.forward};
                for (int k = 0; k < 3; ++k)
                    nv[k] = toFloat(hn::Add(hn::Add(hn::Mul(n[0], hn::Set(d, basis[k].x)), hn::Mul(n[1], hn::Set(d, basis[k].y))),
                                            hn::Mul(n[2], hn::Set(d, basis[k].z))));
            } else {
                for (int k = 0; k < 3; ++k) nv[k] = load(job.normal[k] + i);
            }
            V eye[3] = {zero, zero, hn::Neg(one)};
            if (job.perspective) {
                const V a[3] = {hn::Neg(hn::LoadU(d, job.sx.data() + x)), hn::Set(d, -sy), hn::Neg(one)};
                const V l = hn::Sqrt(hn::Add(hn::Add(hn::Mul(a[0], a[0]), hn::Mul(a[1], a[1])), hn::Mul(a[2], a[2])));
                const V inv = hn::Div(one, l);
                for (int k = 0; k < 3; ++k) eye[k] = hn::IfThenElse(hn::Gt(l, zero), hn::Mul(a[k], inv), a[k]);
            }
            const V dp = hn::Add(hn::Add(hn::Mul(nv[0], eye[0]), hn::Mul(nv[1], eye[1])), hn::Mul(nv[2], eye[2]));
            const V light = toFloat(hn::Add(ambient, hn::Mul(diffuse, hn::IfThenElse(hn::Lt(zero, dp), dp, zero))));
            const auto lit = hn::Eq(dp, dp);
            const V factor = hn::Mul(luminance, light);
            for (V& c : v) c = hn::IfThenElse(lit, hn::Mul(c, factor), c);
        }
        const V k = hn::Mul(strength, load(job.silhouette + i));
        const V a = job.alpha ? load(job.alpha + i) : one;
        const V keep = hn::Sub(one, k);
        const V ao = hn::Add(k, hn::Mul(a, keep));
        const auto covered = hn::Gt(ao, zero);
        for (int ch = 0; ch < 3; ++ch) {
            const V over = hn::Div(hn::Add(hn::Mul(colour[ch], k), hn::Mul(hn::Mul(v[ch], a), keep)), ao);
            hn::StoreU(hn::DemoteTo(df, hn::IfThenElse(covered, over, v[ch])), df, job.out[ch] + i);
        }
        if (job.outAlpha) hn::StoreU(hn::DemoteTo(df, ao), df, job.outAlpha + i);
        if (x + lanes == w) return w;
    }
}

}  // namespace HWY_NAMESPACE
}  // namespace darkroom::passes
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace darkroom::passes {
HWY_EXPORT(Row);
int shadeRow(const ShadeJob& job, int y) { return HWY_DYNAMIC_DISPATCH(Row)(job, y); }
}  // namespace darkroom::passes
#endif
