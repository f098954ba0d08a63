// The box cascade along rows and columns and the darkening factor, a vector
// of rows (along x) or columns (along y) at a time. Every sample's sums run
// in the same order whatever the vector width, so the bits do not depend on
// the instruction set (nor on the thread count).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/darkening_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "darkening.h"

#include <algorithm>
#include <cmath>
#include <limits>

HWY_BEFORE_NAMESPACE();
namespace darkroom::passes {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using D = hn::ScalableTag<double>;
using DF = hn::Rebind<float, D>;
using V = hn::Vec<D>;

// Positions [lo, hi) along an axis; the image covers [0, n).
struct Extent {
    int lo, hi;
};

// One extended box along an axis, for the W values of each sample (the rows
// of a block, the columns of a strip: samples W floats apart, position p
// stored at p + `origin`): out(p) = the sum over the box around p of the
// input, which is 0 outside its extent; accumulated in double. The W values
// are independent running sums stepped together, which hides the latency of
// each one's chain of additions.
template <int W>
class Box {
public:
    Box(const ExtendedBox& b, Extent in, Extent out, int origin)
        : r_(b.radius), alpha_(b.alpha), in_(in), out_(out), origin_(origin) {}

    // emit(p, k, value) for every output position p and vector k of W.
    template <class Emit>
    HWY_INLINE void run(const float* in, const Emit& emit) const {
        const D d;
        const DF df;
        constexpr int kMaxVectors = W;  // enough for one lane per vector
        const int lanes = int(hn::Lanes(d)), vectors = W / lanes;
        const V alpha = hn::Set(d, alpha_), zero = hn::Zero(d);
        auto at = [&](int p, int k) {
            if (p < in_.lo || p >= in_.hi) return zero;
            return hn::PromoteTo(d, hn::LoadU(df, in + std::size_t(p + origin_) * W + std::size_t(k * lanes)));
        };
        V sum[kMaxVectors];
        for (int k = 0; k < vectors; ++k) {
            sum[k] = zero;
            for (int p = std::max(out_.lo - r_, in_.lo); p <= std::min(out_.lo + r_, in_.hi - 1); ++p)
                sum[k] = hn::Add(sum[k], at(p, k));
        }
        for (int p = out_.lo; p < out_.hi; ++p)
            for (int k = 0; k < vectors; ++k) {
                const V leaving = at(p - r_ - 1, k), next = at(p + r_ + 1, k);
                if (p > out_.lo) sum[k] = hn::Add(sum[k], hn::Sub(at(p + r_, k), leaving));
                emit(p, k, alpha_ > 0.0 ? hn::Add(sum[k], hn::Mul(alpha, hn::Add(leaving, next))) : sum[k]);
            }
    }

    HWY_INLINE void run(const float* in, float* out) const {
        const D d;
        const DF df;
        const std::size_t lanes = hn::Lanes(d);
        run(in, [&](int p, int k, V v) {
            hn::StoreU(hn::DemoteTo(df, v), df, out + std::size_t(p + origin_) * W + std::size_t(k) * lanes);
        });
    }

private:
    int r_;
    double alpha_;
    Extent in_, out_;
    int origin_;
};

// The three boxes along an axis of n samples: box k reads the extent box k - 1
// wrote and writes the margin the later boxes need (cascadeMargin), so the
// cascade is one convolution with its whole kernel, also near the border.
struct Cascade {
    const BoxCascade& boxes;
    int n;
    int origin() const { return cascadeMargin(boxes, 0); }
    int samples() const { return n + 2 * origin(); }
    Extent extent(int k) const {  // what box k - 1 wrote (k = 0: the image)
        const int m = k == 0 ? 0 : cascadeMargin(boxes, k - 1);
        return {-m, n + m};
    }
    template <int W>
    Box<W> box(int k) const {
        return Box<W>(boxes[std::size_t(k)], extent(k), extent(k + 1), origin());
    }
};

// e^x for x <= 0 from multiplies and adds only (the same bits on every
// instruction set): x = n ln2 + r with |r| <= ln2 / 2, e^r by its Taylor
// polynomial to r^7 (relative error < 1e-8, below single precision) in
// Estrin's form, whose short dependency chains keep the pipelines busy, and
// 2^n from the exponent bits. Below -104 the result is 0 (it would round to 0
// in single precision anyway).
HWY_INLINE V expNonPositive(V x) {
    const D d;
    const hn::RebindToUnsigned<D> du;
    const V clamped = hn::Max(x, hn::Set(d, -104.0));
    const V n = hn::Round(hn::Mul(clamped, hn::Set(d, 1.4426950408889634)));
    // ln 2 in two parts; n * 0.693145751953125 is exact (16 significant bits).
    const V r = hn::Sub(hn::Sub(clamped, hn::Mul(n, hn::Set(d, 0.693145751953125))),
                        hn::Mul(n, hn::Set(d, 1.42860682030941723212e-6)));
    auto c = [&](double v) { return hn::Set(d, v); };
    const V r2 = hn::Mul(r, r), r4 = hn::Mul(r2, r2);
    const V p01 = hn::Add(c(1.0), r), p23 = hn::Add(c(1.0 / 2), hn::Mul(c(1.0 / 6), r));
    const V p45 = hn::Add(c(1.0 / 24), hn::Mul(c(1.0 / 120), r)), p67 = hn::Add(c(1.0 / 720), hn::Mul(c(1.0 / 5040), r));
    const V p = hn::Add(hn::Add(p01, hn::Mul(r2, p23)), hn::Mul(r4, hn::Add(p45, hn::Mul(r2, p67))));
    // n + 1023 in the low bits of 2^52 + 1023 + n, shifted into the exponent field.
    const V scale = hn::BitCast(d, hn::ShiftLeft<52>(hn::BitCast(du, hn::Add(n, hn::Set(d, 4503599627370496.0 + 1023.0)))));
    return hn::IfThenElseZero(hn::Ge(x, hn::Set(d, -104.0)), hn::Mul(p, scale));
}

// One extended box along a row held in a buffer of `length` floats (position
// p at p + origin, 0 outside the input's extent): for p in `extent`, out(p) =
// the sum over [p - r, p + r] as a sum of power-of-two spans (levels[b][p] = the sum
// of the 2^b samples from p, each level the sum of two of the one below), the
// spans taken from the largest down, plus alpha times the two end samples.
// Every sum is of non-negative numbers in an order fixed by the box alone (not
// by the vector width): single precision is accurate and the bits are the
// same on every instruction set.
void BoxAlongRow(const float* in, float* out, float* levels, Extent extent, const ExtendedBox& b, int origin,
                 int length) {
    const hn::ScalableTag<float> df;
    const int lanes = int(hn::Lanes(df));
    const int r = b.radius, width = 2 * r + 1;
    int top = 0;
    while ((2 << top) <= width) ++top;
    const float* level[32];
    level[0] = in + origin;
    const int lo = extent.lo - r - 1, hi = extent.hi + r + 1;  // positions the levels are needed at
    for (int j = 1; j <= top; ++j) {
        float* l = levels + std::size_t(j - 1) * std::size_t(length) + origin;
        const int half = 1 << (j - 1);
        for (int p = lo; p < hi; p += lanes)
            hn::StoreU(hn::Add(hn::LoadU(df, level[j - 1] + p), hn::LoadU(df, level[j - 1] + p + half)), df, l + p);
        level[j] = l;
    }
    const auto alpha = hn::Set(df, float(b.alpha));
    const bool ends = b.alpha > 0.0;
    for (int p = extent.lo; p < extent.hi; p += lanes) {
        int start = p - r;
        auto sum = hn::LoadU(df, level[top] + start);
        start += 1 << top;
        for (int j = top - 1; j >= 0; --j)
            if (width & (1 << j)) {
                sum = hn::Add(sum, hn::LoadU(df, level[j] + start));
                start += 1 << j;
            }
        if (ends) sum = hn::Add(sum, hn::Mul(alpha, hn::Add(hn::LoadU(df, level[0] + p - r - 1), hn::LoadU(df, level[0] + p + r + 1))));
        hn::StoreU(sum, df, out + origin + p);
    }
    // The vectors ran past the extent: outside it the next box must see 0.
    std::fill(out, out + origin + extent.lo, 0.0f);
    std::fill(out + origin + extent.hi, out + length, 0.0f);
}

void BlurRow(const DarkeningJob& job, float reference, int y, const BlurPlanes& planes, float* scratch) {
    const hn::ScalableTag<float> df;
    const int lanes = int(hn::Lanes(df));
    const int w = job.width;
    const Cascade cascade{job.horizontal, w};
    const int origin = rowOrigin(job), length = rowLength(job);
    float* depth[2] = {scratch, scratch + length};
    float* mask[2] = {scratch + 2 * std::size_t(length), scratch + 3 * std::size_t(length)};
    float* levels = scratch + 4 * std::size_t(length);
    const float* row = job.depth + std::size_t(y) * std::size_t(w);
    for (float* b : {depth[0], mask[0]}) {  // 0 outside the row
        std::fill(b, b + origin, 0.0f);
        std::fill(b + origin + w, b + length, 0.0f);
    }
    const auto zero = hn::Zero(df), one = hn::Set(df, 1.0f), ref = hn::Set(df, reference);
    int x = 0;
    for (; x + lanes <= w; x += lanes) {
        const auto z = hn::LoadU(df, row + x);
        const auto surface = hn::Eq(hn::Sub(z, z), zero);
        hn::StoreU(hn::IfThenElseZero(surface, hn::Sub(z, ref)), df, depth[0] + origin + x);
        hn::StoreU(hn::IfThenElseZero(surface, one), df, mask[0] + origin + x);
    }
    for (; x < w; ++x) {
        const float z = row[x];
        const bool surface = z - z == 0.0f;
        depth[0][origin + x] = surface ? z - reference : 0.0f;
        mask[0][origin + x] = surface ? 1.0f : 0.0f;
    }
    for (int k = 0; k < kBoxes; ++k) {
        const ExtendedBox& b = job.horizontal[std::size_t(k)];
        BoxAlongRow(depth[k % 2], depth[(k + 1) % 2], levels, cascade.extent(k + 1), b, origin, length);
        BoxAlongRow(mask[k % 2], mask[(k + 1) % 2], levels, cascade.extent(k + 1), b, origin, length);
    }
    std::copy_n(depth[kBoxes % 2] + origin, w, planes.depth + std::size_t(y) * std::size_t(w));
    std::copy_n(mask[kBoxes % 2] + origin, w, planes.mask + std::size_t(y) * std::size_t(w));
}

void BlurColumnsAndDarken(const DarkeningJob& job, float reference, int x0, const BlurPlanes& planes, float* scratch) {
    const D d;
    const DF df;
    const int w = job.width, h = job.height, columns = std::min(kStripColumns, w - x0);
    const Cascade cascade{job.vertical, h};
    const int origin = cascade.origin();
    const std::size_t size = std::size_t(cascade.samples()) * kStripColumns;
    float* depth[2] = {scratch, scratch + size};
    float* mask[2] = {scratch + 2 * size, scratch + 3 * size};
    float* z = scratch + 4 * size;  // the depth of the strip, then its factor
    double* masked = reinterpret_cast<double*>(z + std::size_t(h) * kStripColumns);  // the mask's last sums
    for (int y = 0; y < h; ++y) {
        const std::size_t from = std::size_t(y) * std::size_t(w) + std::size_t(x0);
        const std::size_t to = std::size_t(y + origin) * kStripColumns;
        // The strip's rows are a row apart in the planes: ask for later ones early.
        if (y + 8 < h) {
            __builtin_prefetch(planes.depth + from + 8 * std::size_t(w));
            __builtin_prefetch(planes.mask + from + 8 * std::size_t(w));
            __builtin_prefetch(job.depth + from + 8 * std::size_t(w));
        }
        std::copy_n(planes.depth + from, columns, depth[0] + to);
        std::copy_n(planes.mask + from, columns, mask[0] + to);
        std::copy_n(job.depth + from, columns, z + std::size_t(y) * kStripColumns);
        for (int c = columns; c < kStripColumns; ++c) {
            depth[0][to + c] = mask[0][to + c] = 0.0f;
            z[std::size_t(y) * kStripColumns + c] = std::numeric_limits<float>::infinity();
        }
    }
    for (int k = 0; k + 1 < kBoxes; ++k) {
        const Box<kStripColumns> box = cascade.box<kStripColumns>(k);
        box.run(depth[k % 2], depth[(k + 1) % 2]);
        box.run(mask[k % 2], mask[(k + 1) % 2]);
    }
    // The last box of the mask, then of the depth with the factor.
    const float* lastDepth = depth[(kBoxes - 1) % 2];
    const float* lastMask = mask[(kBoxes - 1) % 2];
    const Box<kStripColumns> box = cascade.box<kStripColumns>(kBoxes - 1);
    const V zero = hn::Zero(d), one = hn::Set(d, 1.0), ref = hn::Set(d, double(reference));
    const V minusStrength = hn::Set(d, -job.strength), footprint = hn::Set(d, job.footprint);
    const std::size_t lanes = hn::Lanes(d);
    // The mask's sums stay in double for the division.
    box.run(lastMask, [&](int y, int k, V m) { hn::StoreU(m, d, masked + std::size_t(y) * kStripColumns + k * lanes); });
    box.run(lastDepth, [&](int y, int k, V sum) {
        float* out = z + std::size_t(y) * kStripColumns + k * lanes;
        const V depthHere = hn::PromoteTo(d, hn::LoadU(df, out));
        const auto surface = hn::Eq(hn::Sub(depthHere, depthHere), zero);
        const V blurred = hn::Add(hn::Div(sum, hn::LoadU(d, masked + std::size_t(y) * kStripColumns + k * lanes)), ref);
        const V dd = hn::Sub(blurred, depthHere);
        // Scale-free: a depth step is compared with how wide the blur is in
        // the world at this depth.
        const V s = job.perspective ? hn::Mul(footprint, hn::Abs(depthHere)) : footprint;
        const auto darker = hn::And(surface, hn::And(hn::Lt(dd, zero), hn::Gt(s, zero)));
        V f = one;
        if (!hn::AllFalse(d, darker)) {
            f = hn::IfThenElse(darker, expNonPositive(hn::Div(hn::Mul(minusStrength, hn::Neg(dd)), s)), one);
            f = hn::IfThenElseZero(hn::Ge(f, zero), f);
        }
        hn::StoreU(hn::DemoteTo(df, f), df, out);
    });
    for (int y = 0; y < h; ++y)
        std::copy_n(z + std::size_t(y) * kStripColumns, columns, job.factor + std::size_t(y) * std::size_t(w) + std::size_t(x0));
}

float NearestDepth(const float* depth, std::size_t begin, std::size_t end) {
    const hn::ScalableTag<float> df;
    const std::size_t lanes = hn::Lanes(df);
    const auto inf = hn::Set(df, std::numeric_limits<float>::infinity());
    auto nearest = inf;
    std::size_t i = begin;
    for (; i + lanes <= end; i += lanes) {
        const auto z = hn::LoadU(df, depth + i);
        nearest = hn::Min(nearest, hn::IfThenElse(hn::Eq(hn::Sub(z, z), hn::Zero(df)), z, inf));
    }
    float m = hn::GetLane(hn::MinOfLanes(df, nearest));
    for (; i < end; ++i)
        if (depth[i] - depth[i] == 0.0f) m = std::min(m, depth[i]);
    return m;
}

}  // namespace HWY_NAMESPACE
}  // namespace darkroom::passes
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace darkroom::passes {
HWY_EXPORT(BlurRow);
HWY_EXPORT(BlurColumnsAndDarken);
HWY_EXPORT(NearestDepth);
void blurRow(const DarkeningJob& job, float reference, int y, const BlurPlanes& planes, float* scratch) {
    HWY_DYNAMIC_DISPATCH(BlurRow)(job, reference, y, planes, scratch);
}
void blurColumnsAndDarken(const DarkeningJob& job, float reference, int x0, const BlurPlanes& planes, float* scratch) {
    HWY_DYNAMIC_DISPATCH(BlurColumnsAndDarken)(job, reference, x0, planes, scratch);
}
float nearestDepth(const float* depth, std::size_t begin, std::size_t end) {
    return HWY_DYNAMIC_DISPATCH(NearestDepth)(depth, begin, end);
}
}  // namespace darkroom::passes
#endif
