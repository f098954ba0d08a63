#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/fxaa_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "fxaa_simd.h"
#include "luma.h"

#include <algorithm>
#include <cmath>
#include <limits>

HWY_BEFORE_NAMESPACE();
namespace darkroom::fxaa {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DF = hn::ScalableTag<float>;
using VF = hn::Vec<DF>;

std::size_t LumaSpan(const float* r, const float* g, const float* b, const float* alpha, float* luma,
                     std::size_t begin, std::size_t end) {
    const DF df;
    const hn::RebindToSigned<DF> di;
    const std::size_t lanes = hn::Lanes(df);
    if (end - begin < lanes) return begin;
#if HWY_TARGET == HWY_SCALAR
    const float* table = encodeTable();
#else
    const std::uint64_t* pairs = encodePairs();
    const hn::Repartition<std::uint64_t, DF> du64;
    const hn::Repartition<std::int64_t, DF> di64;
    const hn::Half<decltype(di)> dih;
#endif
    const VF zero = hn::Zero(df), one = hn::Set(df, 1.0f), entries = hn::Set(df, float(kEncodeEntries));
    const VF inf = hn::Set(df, std::numeric_limits<float>::infinity());
    const auto last = hn::Set(di, kEncodeEntries - 1);
    // encode (luma.cpp): clamp, sqrt, table entries i and i + 1, linear blend.
    auto encode = [&](VF c) {
        c = hn::IfThenElse(hn::Lt(c, zero), zero, hn::IfThenElse(hn::Lt(one, c), one, c));
        const VF s = hn::Mul(hn::Sqrt(c), entries);
        const auto i = hn::Min(hn::ConvertTo(di, s), last);
        const VF f = hn::Sub(s, hn::ConvertTo(df, i));
#if HWY_TARGET == HWY_SCALAR
        const VF a = hn::GatherIndex(df, table, i), bb = hn::GatherIndex(df, table + 1, i);
#else
        // Entries i and i + 1 with one 64-bit gather per half vector: half
        // the elements of two 32-bit gathers, which bound this loop.
        const VF lo = hn::BitCast(df, hn::GatherIndex(du64, pairs, hn::PromoteTo(di64, hn::LowerHalf(dih, i))));
        const VF hi = hn::BitCast(df, hn::GatherIndex(du64, pairs, hn::PromoteTo(di64, hn::UpperHalf(dih, i))));
        const VF a = hn::ConcatEven(df, hi, lo), bb = hn::ConcatOdd(df, hi, lo);
#endif
        return hn::Add(a, hn::Mul(f, hn::Sub(bb, a)));
    };
    const VF nan = hn::Set(df, std::numeric_limits<float>::quiet_NaN());
    for (std::size_t i = begin;; i += lanes) {
        if (i + lanes > end) i = end - lanes;  // overlap the last vector: pixels are independent
        const VF vr = hn::LoadU(df, r + i), vg = hn::LoadU(df, g + i), vb = hn::LoadU(df, b + i);
        auto ok = hn::And(hn::And(hn::Lt(hn::Abs(vr), inf), hn::Lt(hn::Abs(vg), inf)), hn::Lt(hn::Abs(vb), inf));
        if (alpha) ok = hn::And(ok, hn::Gt(hn::LoadU(df, alpha + i), zero));
        // Lanes that are not blendable get NaN below; keep NaN out of the table index.
        auto encodeOk = [&](VF c) { return encode(hn::IfThenElseZero(ok, c)); };
        const VF y = hn::Add(hn::Add(hn::Mul(hn::Set(df, 0.299f), encodeOk(vr)), hn::Mul(hn::Set(df, 0.587f), encodeOk(vg))),
                             hn::Mul(hn::Set(df, 0.114f), encodeOk(vb)));
        hn::StoreU(hn::IfThenElse(ok, y, nan), df, luma + i);
        if (i + lanes == end) return end;
    }
}

int FlatSpan(const LumaPlane& plane, const Settings& s, const ColourRows& colour, int y, int x0, int x1,
             std::int32_t* edgeXs, std::size_t& edgeCount) {
    const DF df;
    const hn::RebindToSigned<DF> di;
    const int lanes = int(hn::Lanes(df));
    if (x1 - x0 < lanes) return x0;
    int listed = x0;  // the pixels before it are on the list already (the last vector overlaps)
    const std::size_t w = std::size_t(plane.width);
    const float* row = plane.luma + std::size_t(y) * w;
    const VF thresholdMin = hn::Set(df, s.edgeThresholdMin), threshold = hn::Set(df, s.edgeThreshold);
    const VF zero = hn::Zero(df);
    for (int x = x0;; x += lanes) {
        if (x + lanes > x1) x = x1 - lanes;  // overlap the last vector: pixels are independent
        const VF m = hn::LoadU(df, row + x);
        // Reader::at: a NaN neighbour reads as the centre.
        auto at = [&](const float* p) {
            const VF v = hn::LoadU(df, p);
            return hn::IfThenElse(hn::IsNaN(v), m, v);
        };
        const VF n = at(row + x - w), so = at(row + x + w), e = at(row + x + 1), wv = at(row + x - 1);
        const VF hi = hn::Max(hn::Max(hn::Max(m, n), hn::Max(so, e)), wv);
        const VF lo = hn::Min(hn::Min(hn::Min(m, n), hn::Min(so, e)), wv);
        const VF range = hn::Sub(hi, lo);
        const VF scaled = hn::Mul(hi, threshold);
        const VF needed = hn::IfThenElse(hn::Lt(thresholdMin, scaled), scaled, thresholdMin);
        const auto flat = hn::Or(hn::IsNaN(m), hn::Or(hn::Lt(range, needed), hn::Not(hn::Gt(range, zero))));
        const std::size_t i = std::size_t(y) * w + std::size_t(x);
        for (int c = 0; c < 4; ++c)
            if (colour.in[c]) hn::StoreU(hn::LoadU(df, colour.in[c] + i), df, colour.out[c] + i);
        const auto xs = hn::Iota(di, x);
        const auto edge = hn::And(hn::RebindMask(di, hn::Not(flat)), hn::Gt(xs, hn::Set(di, listed - 1)));
        // Compress in a register and store the whole vector: a masked
        // compressing store to memory is microcoded on some x86 cores.
        hn::StoreU(hn::Compress(xs, edge), di, edgeXs + edgeCount);
        edgeCount += hn::CountTrue(di, edge);
        listed = x + lanes;
        if (x + lanes == x1) return x1;
    }
}

using DI = hn::RebindToSigned<DF>;
using VI = hn::Vec<DI>;
using MF = hn::Mask<DF>;

// The luma plane as vectors: Reader::at (fxaa_kernel.cpp) for one lane per
// pixel, clamped to the image, NaN read as the lane's centre.
struct VectorReader {
    const float* luma;
    VI lastX, lastY, width;
    VF centre;

    VF index(VI i) const {
        const VF v = hn::GatherIndex(DF(), luma, i);
        return hn::IfThenElse(hn::IsNaN(v), centre, v);
    }
    VF at(VI x, VI y) const {
        const VI zero = hn::Zero(DI());
        x = hn::Min(hn::Max(x, zero), lastX);
        y = hn::Min(hn::Max(y, zero), lastY);
        return index(hn::Add(hn::Mul(y, width), x));
    }
};

// One lane's edge, as the end-of-edge search walks along it from `along` (x
// for horizontal edges, y for vertical ones): plane index = clamp(position)
// * alongStride + the part across the edge, `base0` on the centre's line and
// `base1` on the neighbour's.
struct EdgeLanes {
    VI along, alongStride, alongLast, base0, base1;
    VF pairAverage, gradientQuarter;
};

// Reader::edgeSample for every lane at `offset` pixels along the edge from
// its pixel. The lanes still searching have all walked the same steps, so the
// offset is one number: floor and fraction are taken once, exactly as
// edgeSample takes them per pixel (the origin is a whole pixel, so
// floor(origin + offset) = origin + floor(offset)). At whole-pixel offsets
// (f = 0) a + f (b - a) is a itself (b - a is finite: luma lies in [0, 1]),
// so b is not read.
VF EdgeSample(const VectorReader& r, const EdgeLanes& e, float offset) {
    const DF df;
    const DI di;
    const float floored = std::floor(offset);
    const float f = offset - floored;
    const VI zero = hn::Zero(di);
    const VI i0 = hn::Add(e.along, hn::Set(di, int(floored)));
    const VI p0 = hn::Mul(hn::Min(hn::Max(i0, zero), e.alongLast), e.alongStride);
    const VF a = hn::Add(r.index(hn::Add(e.base0, p0)), r.index(hn::Add(e.base1, p0)));
    if (f == 0.0f) return hn::Mul(hn::Set(df, 0.5f), a);
    const VI p1 = hn::Mul(hn::Min(hn::Max(hn::Add(i0, hn::Set(di, 1)), zero), e.alongLast), e.alongStride);
    const VF b = hn::Add(r.index(hn::Add(e.base0, p1)), r.index(hn::Add(e.base1, p1)));
    return hn::Mul(hn::Set(df, 0.5f), hn::Add(a, hn::Mul(hn::Set(df, f), hn::Sub(b, a))));
}

struct SearchEnds {
    VF negDistance, negLuma, posDistance, posLuma;
};

// searchEdgeEnd (fxaa_kernel.cpp) both ways for every lane: a lane stops
// sampling a direction once it has found that end; the loop stops when no
// lane samples any more (most edges end within a step or two).
SearchEnds SearchBothWays(const VectorReader& r, const EdgeLanes& e, const Preset& preset) {
    const DF df;
    const auto& steps = preset.steps;
    SearchEnds out{hn::Set(df, steps[0]), hn::Zero(df), hn::Set(df, steps[0]), hn::Zero(df)};
    MF negActive = hn::FirstN(df, hn::Lanes(df)), posActive = negActive;
    float distance = steps[0];  // of every lane still searching, either way
    for (std::size_t k = 1;; ++k) {
        const VF step = hn::Set(df, steps[k]);
        if (!hn::AllFalse(df, negActive)) {
            const VF luma = hn::Sub(EdgeSample(r, e, -distance), e.pairAverage);
            out.negLuma = hn::IfThenElse(negActive, luma, out.negLuma);
            negActive = hn::AndNot(hn::Ge(hn::Abs(luma), e.gradientQuarter), negActive);
            out.negDistance = hn::IfThenElse(negActive, hn::Add(out.negDistance, step), out.negDistance);
        }
        if (!hn::AllFalse(df, posActive)) {
            const VF luma = hn::Sub(EdgeSample(r, e, distance), e.pairAverage);
            out.posLuma = hn::IfThenElse(posActive, luma, out.posLuma);
            posActive = hn::AndNot(hn::Ge(hn::Abs(luma), e.gradientQuarter), posActive);
            out.posDistance = hn::IfThenElse(posActive, hn::Add(out.posDistance, step), out.posDistance);
        }
        distance += steps[k];
        // The last step is a guess taken without a sample, as in searchEdgeEnd.
        if (k + 1 == steps.size() || (hn::AllFalse(df, negActive) && hn::AllFalse(df, posActive))) break;
    }
    return out;
}

// The 3x3 block around each lane's pixel.
struct Block {
    VF m, n, s, e, w, nw, ne, sw, se;
};

Block ReadBlock(const VectorReader& r, VI x, VI y) {
    const DI di;
    const VI one = hn::Set(di, 1);
    const VI xm = hn::Sub(x, one), xp = hn::Add(x, one), ym = hn::Sub(y, one), yp = hn::Add(y, one);
    return {r.centre,   r.at(x, ym),  r.at(x, yp),  r.at(xp, y),  r.at(xm, y),
            r.at(xm, ym), r.at(xp, ym), r.at(xm, yp), r.at(xp, yp)};
}

// decide() for one vector of pixels (x, y): the same operations in the same
// order, branches turned into lane masks. Returns the amount (0 where decide
// returns no blend) and sets `partner` to the neighbour's clamped index.
VF DecideVector(VectorReader& r, const Settings& s, VI x, VI y, VI& partner) {
    const DF df;
    const DI di;
    const VF zero = hn::Zero(df), one = hn::Set(df, 1.0f), two = hn::Set(df, 2.0f);
    r.centre = hn::GatherIndex(df, r.luma, hn::Add(hn::Mul(y, r.width), x));  // not NaN (precondition)
    const Block b = ReadBlock(r, x, y);
    const VF m = b.m;

    // 1. Local contrast (FlatSpan's test).
    const VF rangeMax = hn::Max(hn::Max(hn::Max(hn::Max(m, b.n), b.s), b.e), b.w);
    const VF rangeMin = hn::Min(hn::Min(hn::Min(hn::Min(m, b.n), b.s), b.e), b.w);
    const VF range = hn::Sub(rangeMax, rangeMin);
    const VF scaled = hn::Mul(rangeMax, hn::Set(df, s.edgeThreshold)), thresholdMin = hn::Set(df, s.edgeThresholdMin);
    const VF needed = hn::IfThenElse(hn::Lt(thresholdMin, scaled), scaled, thresholdMin);
    const MF flat = hn::Or(hn::Lt(range, needed), hn::Not(hn::Gt(range, zero)));

    // 2. Orientation.
    auto secondDifference = [&](VF a, VF c, VF centre) { return hn::Abs(hn::Sub(hn::Add(a, c), hn::Mul(two, centre))); };
    const VF edgeHorizontal = hn::Add(hn::Add(secondDifference(b.nw, b.sw, b.w), hn::Mul(two, secondDifference(b.n, b.s, m))),
                                      secondDifference(b.ne, b.se, b.e));
    const VF edgeVertical = hn::Add(hn::Add(secondDifference(b.nw, b.ne, b.n), hn::Mul(two, secondDifference(b.w, b.e, m))),
                                    secondDifference(b.sw, b.se, b.s));
    const MF horizontal = hn::Ge(edgeHorizontal, edgeVertical);

    // 3. Sub-pixel term.
    const VF cross = hn::Add(hn::Add(hn::Add(b.n, b.s), b.w), b.e);
    const VF corners = hn::Add(hn::Add(hn::Add(b.nw, b.ne), b.sw), b.se);
    const VF lowPass = hn::Mul(hn::Add(hn::Mul(two, cross), corners), hn::Set(df, 1.0f / 12.0f));
    const VF subpixC = hn::Min(hn::Max(hn::Div(hn::Abs(hn::Sub(lowPass, m)), range), zero), one);
    const VF subpixF = hn::Mul(hn::Mul(subpixC, subpixC), hn::Sub(hn::Set(df, 3.0f), hn::Mul(two, subpixC)));
    const VF subpixBlend = hn::Mul(hn::Mul(subpixF, subpixF), hn::Set(df, s.subpix));

    // 4. The edge pair.
    const VF before = hn::IfThenElse(horizontal, b.n, b.w), after = hn::IfThenElse(horizontal, b.s, b.e);
    const VF gradBefore = hn::Sub(before, m), gradAfter = hn::Sub(after, m);
    const MF towardsBefore = hn::Ge(hn::Abs(gradBefore), hn::Abs(gradAfter));
    const VI side = hn::IfThenElse(hn::RebindMask(di, towardsBefore), hn::Set(di, -1), hn::Set(di, 1));
    const VF pairAverage = hn::Mul(hn::Set(df, 0.5f), hn::Add(m, hn::IfThenElse(towardsBefore, before, after)));
    const MF centreBelowPair = hn::Lt(hn::Sub(m, pairAverage), zero);
    const auto horizontalI = hn::RebindMask(di, horizontal);

    // 5. Both ends, along x for horizontal edges and along y for vertical ones.
    const VI across = hn::IfThenElse(horizontalI, y, x), acrossLast = hn::IfThenElse(horizontalI, r.lastY, r.lastX);
    const VI acrossStride = hn::IfThenElse(horizontalI, r.width, hn::Set(di, 1));
    const VI neighbour = hn::Min(hn::Max(hn::Add(across, side), hn::Zero(di)), acrossLast);
    EdgeLanes e;
    e.alongStride = hn::IfThenElse(horizontalI, hn::Set(di, 1), r.width);
    e.alongLast = hn::IfThenElse(horizontalI, r.lastX, r.lastY);
    e.base0 = hn::Mul(across, acrossStride);
    e.base1 = hn::Mul(neighbour, acrossStride);
    e.along = hn::IfThenElse(horizontalI, x, y);
    e.pairAverage = pairAverage;
    e.gradientQuarter = hn::Mul(hn::Set(df, 0.25f), hn::Max(hn::Abs(gradBefore), hn::Abs(gradAfter)));
    const SearchEnds ends = SearchBothWays(r, e, *s.preset);

    // 6. The nearer end decides.
    const MF negNearer = hn::Lt(ends.negDistance, ends.posDistance);
    const VF nearest = hn::Min(ends.negDistance, ends.posDistance);
    const MF goodSpan = hn::Xor(hn::Lt(hn::IfThenElse(negNearer, ends.negLuma, ends.posLuma), zero), centreBelowPair);
    const VF edgeBlend = hn::IfThenElseZero(
        goodSpan, hn::Sub(hn::Set(df, 0.5f), hn::Div(nearest, hn::Add(ends.negDistance, ends.posDistance))));
    const VF amount = hn::Min(hn::Max(hn::Max(edgeBlend, subpixBlend), zero), one);

    // The neighbour's position: across the edge by `side`, clamped.
    const VI own = hn::Add(hn::Mul(y, r.width), x);
    partner = hn::IfThenElse(hn::RebindMask(di, flat), own,
                             hn::Add(hn::Mul(e.along, e.alongStride), e.base1));
    return hn::IfThenZeroElse(flat, amount);
}

void DecideList(const LumaPlane& plane, const Settings& s, const std::int32_t* xs, const std::int32_t* ys,
                std::size_t count, float* amount, std::int32_t* partner) {
    const DF df;
    const DI di;
    const std::size_t lanes = hn::Lanes(df);
    if (count == 0) return;
    VectorReader r{plane.luma, hn::Set(di, plane.width - 1), hn::Set(di, plane.height - 1), hn::Set(di, plane.width),
                   hn::Zero(df)};
    // Fewer pixels than lanes: fill the vector with copies of the last one.
    HWY_ALIGN std::int32_t padX[HWY_MAX_BYTES / 4], padY[HWY_MAX_BYTES / 4], padPartner[HWY_MAX_BYTES / 4];
    HWY_ALIGN float padAmount[HWY_MAX_BYTES / 4];
    if (count < lanes) {
        for (std::size_t k = 0; k < lanes; ++k) {
            padX[k] = xs[std::min(k, count - 1)];
            padY[k] = ys[std::min(k, count - 1)];
        }
        VI p;
        hn::Store(DecideVector(r, s, hn::Load(di, padX), hn::Load(di, padY), p), df, padAmount);
        hn::Store(p, di, padPartner);
        std::copy_n(padAmount, count, amount);
        std::copy_n(padPartner, count, partner);
        return;
    }
    for (std::size_t k = 0;; k += lanes) {
        if (k + lanes > count) k = count - lanes;  // overlap the last vector: pixels are independent
        VI p;
        hn::StoreU(DecideVector(r, s, hn::LoadU(di, xs + k), hn::LoadU(di, ys + k), p), df, amount + k);
        hn::StoreU(p, di, partner + k);
        if (k + lanes == count) return;
    }
}

}  // namespace HWY_NAMESPACE
}  // namespace darkroom::fxaa
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace darkroom::fxaa {
HWY_EXPORT(LumaSpan);
HWY_EXPORT(FlatSpan);
HWY_EXPORT(DecideList);
std::size_t lumaSpan(const float* r, const float* g, const float* b, const float* alpha, float* luma,
                     std::size_t begin, std::size_t end) {
    return HWY_DYNAMIC_DISPATCH(LumaSpan)(r, g, b, alpha, luma, begin, end);
}
int flatSpan(const LumaPlane& plane, const Settings& s, const ColourRows& colour, int y, int x0, int x1,
             std::int32_t* edgeXs, std::size_t& edgeCount) {
    return HWY_DYNAMIC_DISPATCH(FlatSpan)(plane, s, colour, y, x0, x1, edgeXs, edgeCount);
}
void decideList(const LumaPlane& plane, const Settings& s, const std::int32_t* xs, const std::int32_t* ys,
                std::size_t count, float* amount, std::int32_t* partner) {
    HWY_DYNAMIC_DISPATCH(DecideList)(plane, s, xs, ys, count, amount, partner);
}
}  // namespace darkroom::fxaa
#endif
