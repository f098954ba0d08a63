// The hexagon gather for a vector of pixels of a row at a time. Both passes
// step along fixed directions, the same offset for every pixel of a vector,
// so every tap is a plain load. The first pass's partial sums live in a ring
// of rows (the reach of the second pass above and below the row it finishes)
// per band of rows, not in a plane of the whole image.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/gather_hexagon.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "gathers.h"
#include "layer_rules-inl.h"

#include <darkroom/context.h>

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#ifndef DARKROOM_SSDOF_HEXAGON_ONCE
#define DARKROOM_SSDOF_HEXAGON_ONCE
namespace darkroom::ssdof {

// A regular hexagon of circumradius n is the union of three rhombi spanned by
// pairs of the unit vectors v0, v1, v2 at 120 degrees (corners at +-v_k). A
// rhombus {a vi + b vj} is a box blur along vi followed by one along vj, so:
//   pass 1:  A  = blur along v0 over t = 0..n
//            S  = A + blur along v1 over t = 1..n
//   pass 2:  out = A(p) + sum_{t=1..n} A(p + t v1) + sum_{t=1..n} S(p + t v2)
// covers rhombus (v0,v1), rhombus (v0,v2) and rhombus (v1,v2) without its two
// edges, i.e. every lattice point of the hexagon exactly once: 3n^2 + 3n + 1
// taps from 4n + 1 reads per pass. The gather is the hexagon mirrored through
// p, which is the same hexagon. Each layer carries sums and weights through
// the passes and is normalised only at the end.
struct HexagonSteps {
    std::array<std::vector<std::array<int, 2>>, 3> dir;  // rounded offsets t * v_k, t = 0..max
};

// The partial sums of pass 1 per pixel, one plane each in a ring row: A and S
// of the focus/far layer (colour, weight) and of the near layer (colour,
// weight, the largest near CoC summed).
enum Field { kBackA = 0, kBackS = 5, kNearA = 10, kNearS = 16, kFields = 22 };
constexpr int kReach = 5;  // offset of the reach within a near partial

struct Ring {
    float* data;
    int rows, stride;
    float* field(int y, int f) const {
        const int slot = ((y % rows) + rows) % rows;
        return data + (std::size_t(slot) * kFields + std::size_t(f)) * std::size_t(stride);
    }
};

}  // namespace darkroom::ssdof
#endif

HWY_BEFORE_NAMESPACE();
namespace darkroom::ssdof {
namespace HWY_NAMESPACE {

// std::round(radius) lattice points of a hexagon: a near sample spreads
// weight 1 over its whole kernel, 1/H per tap.
HWY_INLINE VF HexagonTaps(VF radius) {
    const DF d;
    const VF n = RoundHalfAway(radius), three = hn::Set(d, 3.0f);
    return hn::Add(hn::Add(hn::Mul(hn::Mul(three, n), n), hn::Mul(three, n)), hn::Set(d, 1.0f));
}

// Pass 1 for row y: blur1D along v0 (t from 0) and along v1 (t from 1) of
// both layers, into the ring.
void FirstPass(const WorkImage& w, const HexagonSteps& steps, const Ring& ring, int y) {
    const DF d;
    const int lanes = int(hn::Lanes(d));
    const VF zero = hn::Zero(d), one = hn::Set(d, 1.0f);
    for (int x0 = 0; x0 < w.width; x0 += lanes) {
        const int count = std::min(lanes, w.width - x0);
        const std::size_t i = w.index(x0, y);
        // Past the image's right edge: CoC 0, no taps.
        const VF sp = hn::IfThenElseZero(hn::FirstN(d, std::size_t(count)), hn::LoadU(d, w.coc.data() + i));
        const VF rp = hn::Abs(sp);
        const VF nBack = RoundHalfAway(rp);
        const float nNear = float(std::lround(w.reachAt(x0, y)));
        const int last = int(std::max(hn::GetLane(hn::MaxOfLanes(d, nBack)), nNear));
        Layer back[2] = {Layer::zero(), Layer::zero()}, nearL[2] = {Layer::zero(), Layer::zero()};
        VF reach[2] = {zero, zero};
        for (int k = 0; k < 2; ++k)
            for (int t = k; t <= last; ++t) {
                const auto& o = steps.dir[std::size_t(k)][std::size_t(t)];
                const std::size_t j = w.index(x0 + o[0], y + o[1]);
                const VF sq = hn::LoadU(d, w.coc.data() + j);
                const VF tv = hn::Set(d, float(t));
                const MF inside = hn::Not(hn::IsNaN(sq));
                const VF c[4] = {hn::LoadU(d, w.r.data() + j), hn::LoadU(d, w.g.data() + j), hn::LoadU(d, w.b.data() + j),
                                 hn::LoadU(d, w.a.data() + j)};
                const MF inBack = hn::And(inside, hn::Le(tv, nBack));
                const VF wb = hn::IfThenElseZero(inBack, BackgroundWeight(sp, rp, hn::IfThenElseZero(inside, sq), tv));
                back[k].add(wb, c[0], c[1], c[2], c[3]);
                if (float(t) <= nNear) {
                    const MF isNear = hn::And(inside, ReachesAsNear(sp, sq, tv));
                    const VF wn = hn::IfThenElseZero(isNear, hn::Div(one, HexagonTaps(hn::Neg(sq))));
                    nearL[k].add(wn, c[0], c[1], c[2], c[3]);
                    reach[k] = hn::IfThenElse(hn::And(isNear, hn::Lt(reach[k], hn::Neg(sq))), hn::Neg(sq), reach[k]);
                }
            }
        // S = A + the blur along v1 (Rgba::add with weight 1: a plain sum).
        const std::size_t col = std::size_t(x0 + w.pad);
        auto store = [&](int f, VF v) { hn::StoreU(v, d, ring.field(y, f) + col); };
        auto storeLayer = [&](int f, const Layer& l) {
            store(f, l.r);
            store(f + 1, l.g);
            store(f + 2, l.b);
            store(f + 3, l.a);
            store(f + 4, l.weight);
        };
        auto sum = [](const Layer& a, const Layer& b) {
            return Layer{hn::Add(a.r, b.r), hn::Add(a.g, b.g), hn::Add(a.b, b.b), hn::Add(a.a, b.a), hn::Add(a.weight, b.weight)};
        };
        storeLayer(kBackA, back[0]);
        storeLayer(kBackS, sum(back[0], back[1]));
        storeLayer(kNearA, nearL[0]);
        storeLayer(kNearS, sum(nearL[0], nearL[1]));
        store(kNearA + kReach, reach[0]);
        // std::max(nearS.reach, near1.reach)
        store(kNearS + kReach, hn::IfThenElse(hn::Lt(reach[0], reach[1]), reach[1], reach[0]));
    }
}

// Pass 2 for row y: A(p) + A along v1 + S along v2 of both layers, then the
// composite.
void SecondPass(const WorkImage& w, const HexagonSteps& steps, const Ring& ring, int y, const Output& out) {
    const DF d;
    const int lanes = int(hn::Lanes(d));
    const VF zero = hn::Zero(d), half = hn::Set(d, 0.5f), focus = hn::Set(d, kInFocus);
    for (int x0 = 0; x0 < w.width; x0 += lanes) {
        const int count = std::min(lanes, w.width - x0);
        const std::size_t i = w.index(x0, y);
        const VF sp = hn::IfThenElseZero(hn::FirstN(d, std::size_t(count)), hn::LoadU(d, w.coc.data() + i));
        const VF rp = hn::Abs(sp);
        const std::size_t col = std::size_t(x0 + w.pad);
        auto own = [&](int f) { return hn::LoadU(d, ring.field(y, f) + col); };
        Layer nearL{own(kNearA), own(kNearA + 1), own(kNearA + 2), own(kNearA + 3), own(kNearA + 4)};
        const int nNear = int(std::lround(w.reachAt(x0, y)));
        for (int t = 1; t <= nNear; ++t)
            for (int k = 1; k <= 2; ++k) {
                const auto& o = steps.dir[std::size_t(k)][std::size_t(t)];
                const MF inside = hn::Not(hn::IsNaN(hn::LoadU(d, w.coc.data() + w.index(x0 + o[0], y + o[1]))));
                const int f = k == 1 ? kNearA : kNearS;
                auto at = [&](int g) { return hn::LoadU(d, ring.field(y + o[1], f + g) + col + o[0]); };
                const VF weight = at(4);
                const MF use = hn::AndNot(hn::Or(hn::Eq(weight, zero), hn::Gt(hn::Set(d, float(t)), hn::Add(at(kReach), half))), inside);
                nearL.addWhere(use, at);
            }
        const MF unchanged = hn::And(hn::Lt(rp, focus), hn::Eq(nearL.weight, zero));
        const VF self[4] = {hn::LoadU(d, w.r.data() + i), hn::LoadU(d, w.g.data() + i), hn::LoadU(d, w.b.data() + i),
                            hn::LoadU(d, w.a.data() + i)};
        const std::size_t o = std::size_t(y) * std::size_t(w.width) + std::size_t(x0);
        Layer backL{own(kBackA), own(kBackA + 1), own(kBackA + 2), own(kBackA + 3), own(kBackA + 4)};
        const MF inImage = hn::FirstN(d, std::size_t(count));
        if (!hn::AllTrue(d, hn::Or(unchanged, hn::Not(inImage)))) {
            const VF nBack = RoundHalfAway(rp);
            const int last = int(hn::GetLane(hn::MaxOfLanes(d, nBack)));
            for (int t = 1; t <= last; ++t)
                for (int k = 1; k <= 2; ++k) {
                    const auto& o2 = steps.dir[std::size_t(k)][std::size_t(t)];
                    const VF sq = hn::LoadU(d, w.coc.data() + w.index(x0 + o2[0], y + o2[1]));
                    const MF inside = hn::Not(hn::IsNaN(sq));
                    const VF tv = hn::Set(d, float(t));
                    // The intermediate pixel stands for its own CoC.
                    const VF wq = BackgroundWeight(sp, rp, hn::IfThenElseZero(inside, sq), tv);
                    const MF use = hn::And(hn::And(inside, hn::Le(tv, nBack)), hn::Gt(wq, zero));
                    const int f = k == 1 ? kBackA : kBackS;
                    backL.addWhere(use, [&](int g) { return hn::LoadU(d, ring.field(y + o2[1], f + g) + col + o2[0]); });
                }
        }
        Finish(out, o, count, nearL, backL, self[0], self[1], self[2], self[3], unchanged);
    }
}

}  // namespace HWY_NAMESPACE
}  // namespace darkroom::ssdof
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace darkroom::ssdof {
HWY_EXPORT(FirstPass);
HWY_EXPORT(SecondPass);

namespace {

std::vector<std::array<int, 2>> steps(double angle, int count) {
    std::vector<std::array<int, 2>> s(static_cast<std::size_t>(count) + 1);
    // Image rows go down: "up" rotated clockwise by angle is (sin, -cos).
    for (int t = 0; t <= count; ++t)
        s[std::size_t(t)] = {int(std::lround(t * std::sin(angle))), int(std::lround(-t * std::cos(angle)))};
    return s;
}

}  // namespace

void gatherHexagon(const WorkImage& w, double rotationDegrees, Context& ctx, const Output& out) {
    const double pi = std::numbers::pi;
    // Every tap is within pad - 1 pixels (buildWorkImage): t runs to round(|CoC|) <= pad - 2.
    const int maxSteps = w.pad - 1;
    HexagonSteps hex;
    for (int k = 0; k < 3; ++k) hex.dir[std::size_t(k)] = steps((rotationDegrees + 120.0 * k) * pi / 180.0, maxSteps);
    // Bands of rows, each with a ring of the rows its second pass reads
    // (pass 1 of the rows within the reach above a band is done again there:
    // its result depends on the pixel alone, not on the band).
    const int reach = maxSteps;
    const int band = std::max(128, 8 * reach);
    const int bands = (w.height + band - 1) / band;
    ctx.parallelFor(0, bands, 1, [&](int b0, int b1) {
        thread_local std::vector<float> storage;
        const Ring ring{nullptr, 2 * reach + 2, w.stride};
        storage.resize(std::size_t(ring.rows) * kFields * std::size_t(ring.stride));
        const Ring r{storage.data(), ring.rows, ring.stride};
        for (int b = b0; b < b1; ++b) {
            const int y0 = b * band, y1 = std::min(w.height, y0 + band);
            int done = std::max(0, y0 - reach);  // the next row pass 1 has to do
            for (int y = y0; y < y1; ++y) {
                for (; done <= std::min(w.height - 1, y + reach); ++done) HWY_DYNAMIC_DISPATCH(FirstPass)(w, hex, r, done);
                HWY_DYNAMIC_DISPATCH(SecondPass)(w, hex, r, y, out);
            }
        }
    });
}

}  // namespace darkroom::ssdof
#endif
