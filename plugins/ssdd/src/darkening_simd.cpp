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
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>

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
// of a block, the columns of a strip): out(p) = the sum over the box around p
// of the input, which is 0 outside its extent; accumulated in double. The W
// values are independent running sums stepped together, which hides the
// latency of each one's chain of additions, and each lane's sums run in the
// same order whatever the vector width.
template <int W>
class Box {
public:
    Box(const ExtendedBox& b, Extent in, Extent out) : r_(b.radius), alpha_(b.alpha), in_(in), out_(out) {}

    // emit(p, k, value) for every output position p and vector k of W. The
    // input's W values of position p start at in + p * stride (p < 0 in the
    // margins); a stride wider than W reads a strip straight from a plane.
    template <class Emit>
    HWY_INLINE void run(const float* in, std::ptrdiff_t stride, const Emit& emit) const {
        const D d;
        const DF df;
        constexpr int kMaxVectors = W;  // enough for one lane per vector
        const int lanes = int(hn::Lanes(d)), vectors = W / lanes;
        const V alpha = hn::Set(d, alpha_), zero = hn::Zero(d);
        auto at = [&](int p, int k) {
            if (p < in_.lo || p >= in_.hi) return zero;
            return hn::PromoteTo(d, hn::LoadU(df, in + p * stride + k * lanes));
        };
        // A plane's rows are far apart: ask for the ones entering the box early.
        const bool plane = stride != W;
        V sum[kMaxVectors];
        for (int k = 0; k < vectors; ++k) {
            sum[k] = zero;
            for (int p = std::max(out_.lo - r_, in_.lo); p <= std::min(out_.lo + r_, in_.hi - 1); ++p)
                sum[k] = hn::Add(sum[k], at(p, k));
        }
        for (int p = out_.lo; p < out_.hi; ++p) {
            if (plane && p + r_ + 25 < in_.hi)
                for (int c = 0; c < W; c += 16) __builtin_prefetch(in + (p + r_ + 25) * stride + c);
            for (int k = 0; k < vectors; ++k) {
                const V leaving = at(p - r_ - 1, k), next = at(p + r_ + 1, k);
                if (p > out_.lo) sum[k] = hn::Add(sum[k], hn::Sub(at(p + r_, k), leaving));
                emit(p, k, alpha_ > 0.0 ? hn::Add(sum[k], hn::Mul(alpha, hn::Add(leaving, next))) : sum[k]);
            }
        }
    }

    // Into a block or strip: position p's W values at out + p * W.
    HWY_INLINE void run(const float* in, std::ptrdiff_t stride, float* out) const {
        const D d;
        const DF df;
        const std::size_t lanes = hn::Lanes(d);
        run(in, stride, [&](int p, int k, V v) {
            hn::StoreU(hn::DemoteTo(df, v), df, out + std::ptrdiff_t(p) * W + std::ptrdiff_t(k * lanes));
        });
    }

private:
    int r_;
    double alpha_;
    Extent in_, out_;
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
        return Box<W>(boxes[std::size_t(k)], extent(k), extent(k + 1));
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

#if HWY_TARGET != HWY_SCALAR
using D4 = hn::FixedTag<float, 4>;
using V4 = hn::Vec<D4>;

// v[i] = row i of a 4 x 4 block becomes column i.
HWY_INLINE void Transpose4(V4 v[4]) {
    const D4 d4;
    const hn::Repartition<std::uint64_t, D4> d64;
    const V4 t0 = hn::InterleaveLower(d4, v[0], v[1]), t1 = hn::InterleaveLower(d4, v[2], v[3]);
    const V4 t2 = hn::InterleaveUpper(d4, v[0], v[1]), t3 = hn::InterleaveUpper(d4, v[2], v[3]);
    v[0] = hn::BitCast(d4, hn::InterleaveLower(d64, hn::BitCast(d64, t0), hn::BitCast(d64, t1)));
    v[1] = hn::BitCast(d4, hn::InterleaveUpper(d64, hn::BitCast(d64, t0), hn::BitCast(d64, t1)));
    v[2] = hn::BitCast(d4, hn::InterleaveLower(d64, hn::BitCast(d64, t2), hn::BitCast(d64, t3)));
    v[3] = hn::BitCast(d4, hn::InterleaveUpper(d64, hn::BitCast(d64, t2), hn::BitCast(d64, t3)));
}
#endif

// kBlockRows rows of depth into a block (x of row r at x * kBlockRows + r):
// Z - reference and 1 where there is a surface, 0 and 0 where there is none.
void RowsIntoBlock(const float* const* row, int w, float reference, float* depth, float* mask) {
    constexpr int R = kBlockRows;
    int x0 = 0;
#if HWY_TARGET != HWY_SCALAR
    const D4 d4;
    const V4 zero = hn::Zero(d4), one = hn::Set(d4, 1.0f), ref = hn::Set(d4, reference);
    for (; x0 + 4 <= w; x0 += 4)
        for (int g = 0; g < R; g += 4) {
            V4 z[4], m[4];
            for (int i = 0; i < 4; ++i) {
                const V4 a = hn::LoadU(d4, row[g + i] + x0);
                const auto surface = hn::Eq(hn::Sub(a, a), zero);
                z[i] = hn::IfThenElseZero(surface, hn::Sub(a, ref));
                m[i] = hn::IfThenElseZero(surface, one);
            }
            Transpose4(z);
            Transpose4(m);
            for (int j = 0; j < 4; ++j) {
                hn::StoreU(z[j], d4, depth + std::size_t(x0 + j) * R + std::size_t(g));
                hn::StoreU(m[j], d4, mask + std::size_t(x0 + j) * R + std::size_t(g));
            }
        }
#endif
    for (int x = x0; x < w; ++x)
        for (int r = 0; r < R; ++r) {
            const float z = row[r][x];
            const bool surface = z - z == 0.0f;
            depth[std::size_t(x) * R + std::size_t(r)] = surface ? z - reference : 0.0f;
            mask[std::size_t(x) * R + std::size_t(r)] = surface ? 1.0f : 0.0f;
        }
}

// The first `rows` rows of a block back into a plane of row stride w.
void BlockIntoRows(const float* block, int w, int rows, float* out) {
    constexpr int R = kBlockRows;
    int x0 = 0;
#if HWY_TARGET != HWY_SCALAR
    const D4 d4;
    // Four rows at a time along the whole width: four sequential streams of
    // stores rather than sixteen interleaved ones.
    const int whole = w - w % 4;
    for (int g = 0; g < rows; g += 4)
        for (int x = 0; x < whole; x += 4) {
            V4 v[4];
            for (int j = 0; j < 4; ++j) v[j] = hn::LoadU(d4, block + std::size_t(x + j) * R + std::size_t(g));
            Transpose4(v);
            for (int i = 0; i < 4 && g + i < rows; ++i) hn::StoreU(v[i], d4, out + std::size_t(g + i) * std::size_t(w) + std::size_t(x));
        }
    x0 = whole;
#endif
    for (int x = x0; x < w; ++x)
        for (int r = 0; r < rows; ++r) out[std::size_t(r) * std::size_t(w) + std::size_t(x)] = block[std::size_t(x) * R + std::size_t(r)];
}

void BlurRows(const DarkeningJob& job, float reference, int y0, const BlurPlanes& planes, float* scratch) {
    constexpr int R = kBlockRows;
    const int w = job.width, rows = std::min(R, job.height - y0);
    const Cascade cascade{job.horizontal, w};
    const std::size_t size = std::size_t(cascade.samples()) * R, origin = std::size_t(cascade.origin()) * R;
    // Position 0 of each block; the margins before and after it.
    float* depth[2] = {scratch + origin, scratch + size + origin};
    float* mask[2] = {scratch + 2 * size + origin, scratch + 3 * size + origin};
    float* noSurface = scratch + 4 * size;
    const float* row[R];
    for (int r = 0; r < R; ++r) row[r] = r < rows ? job.depth + std::size_t(y0 + r) * std::size_t(w) : noSurface;
    if (rows < R) std::fill_n(noSurface, w, std::numeric_limits<float>::infinity());
    RowsIntoBlock(row, w, reference, depth[0], mask[0]);
    for (int k = 0; k < kBoxes; ++k) {
        const Box<R> box = cascade.box<R>(k);
        box.run(depth[k % 2], R, depth[(k + 1) % 2]);
        box.run(mask[k % 2], R, mask[(k + 1) % 2]);
    }
    BlockIntoRows(depth[kBoxes % 2], w, rows, planes.depth + std::size_t(y0) * std::size_t(w));
    BlockIntoRows(mask[kBoxes % 2], w, rows, planes.mask + std::size_t(y0) * std::size_t(w));
}

void BlurColumnsAndDarken(const DarkeningJob& job, float reference, int x0, const BlurPlanes& planes, float* scratch) {
    constexpr int C = kStripColumns;
    const D d;
    const DF df;
    const int w = job.width, h = job.height, columns = std::min(C, w - x0);
    const Cascade cascade{job.vertical, h};
    const std::size_t size = std::size_t(cascade.samples()) * C, origin = std::size_t(cascade.origin()) * C;
    float* depth[2] = {scratch + origin, scratch + size + origin};
    float* mask[2] = {scratch + 2 * size + origin, scratch + 3 * size + origin};
    float* z = scratch + 4 * size;  // a narrow strip's depth, then its factor
    double* masked = reinterpret_cast<double*>(z + std::size_t(h) * C);  // the mask's last sums
    // A whole strip is read from the planes and the depth and its factor
    // written in place, C floats of each row apart; a narrow one is copied,
    // as reading C floats would run past the last row.
    const float* depthIn = planes.depth + x0;
    const float* maskIn = planes.mask + x0;
    const float* zIn = job.depth + x0;
    float* factorOut = job.factor + x0;
    std::ptrdiff_t stride = w;
    if (columns < C) {
        for (int y = 0; y < h; ++y) {
            const std::size_t from = std::size_t(y) * std::size_t(w) + std::size_t(x0), to = std::size_t(y) * C;
            std::copy_n(planes.depth + from, columns, depth[0] + to);
            std::copy_n(planes.mask + from, columns, mask[0] + to);
            std::copy_n(job.depth + from, columns, z + to);
            std::fill(depth[0] + to + columns, depth[0] + to + C, 0.0f);
            std::fill(mask[0] + to + columns, mask[0] + to + C, 0.0f);
            std::fill(z + to + columns, z + to + C, std::numeric_limits<float>::infinity());
        }
        depthIn = depth[0];
        maskIn = mask[0];
        zIn = factorOut = z;
        stride = C;
    }
    const Box<C> first = cascade.box<C>(0);
    first.run(depthIn, stride, depth[1]);
    first.run(maskIn, stride, mask[1]);
    for (int k = 1; k + 1 < kBoxes; ++k) {
        const Box<C> box = cascade.box<C>(k);
        box.run(depth[k % 2], C, depth[(k + 1) % 2]);
        box.run(mask[k % 2], C, mask[(k + 1) % 2]);
    }
    // The last box of the mask, then of the depth with the factor.
    const float* lastDepth = depth[(kBoxes - 1) % 2];
    const float* lastMask = mask[(kBoxes - 1) % 2];
    const Box<C> box = cascade.box<C>(kBoxes - 1);
    const V zero = hn::Zero(d), one = hn::Set(d, 1.0), ref = hn::Set(d, double(reference));
    const V minusStrength = hn::Set(d, -job.strength), footprint = hn::Set(d, job.footprint);
    const std::ptrdiff_t lanes = std::ptrdiff_t(hn::Lanes(d));
    // The mask's sums stay in double for the division.
    box.run(lastMask, C, [&](int y, int k, V m) { hn::StoreU(m, d, masked + std::ptrdiff_t(y) * C + k * lanes); });
    box.run(lastDepth, C, [&](int y, int k, V sum) {
        const std::ptrdiff_t at = std::ptrdiff_t(y) * stride + k * lanes;
        if (k == 0 && stride != C && y + 24 < h)
            for (int c = 0; c < C; c += 16) __builtin_prefetch(zIn + at + 24 * stride + c);
        const V depthHere = hn::PromoteTo(d, hn::LoadU(df, zIn + at));
        const auto surface = hn::Eq(hn::Sub(depthHere, depthHere), zero);
        const V blurred = hn::Add(hn::Div(sum, hn::LoadU(d, masked + std::ptrdiff_t(y) * C + k * lanes)), ref);
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
        hn::StoreU(hn::DemoteTo(df, f), df, factorOut + at);
    });
    if (columns < C)
        for (int y = 0; y < h; ++y)
            std::copy_n(z + std::size_t(y) * C, columns, job.factor + std::size_t(y) * std::size_t(w) + std::size_t(x0));
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
HWY_EXPORT(BlurRows);
HWY_EXPORT(BlurColumnsAndDarken);
HWY_EXPORT(NearestDepth);
void blurRows(const DarkeningJob& job, float reference, int y0, const BlurPlanes& planes, float* scratch) {
    HWY_DYNAMIC_DISPATCH(BlurRows)(job, reference, y0, planes, scratch);
}
void blurColumnsAndDarken(const DarkeningJob& job, float reference, int x0, const BlurPlanes& planes, float* scratch) {
    HWY_DYNAMIC_DISPATCH(BlurColumnsAndDarken)(job, reference, x0, planes, scratch);
}
float nearestDepth(const float* depth, std::size_t begin, std::size_t end) {
    return HWY_DYNAMIC_DISPATCH(NearestDepth)(depth, begin, end);
}
}  // namespace darkroom::passes
#endif
