// The disc gather for a vector of pixels of a row at a time. The near layer's
// spiral is scaled to the tile's near reach, the same for every pixel of a
// vector (vectors never straddle tiles), so its taps are plain loads; the far
// layer's is scaled to each pixel's own CoC, so its taps are gathers.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/gather_disc.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "gathers.h"
#include "layer_rules-inl.h"

#include <darkroom/context.h>

#include <cmath>
#include <numbers>

HWY_BEFORE_NAMESPACE();
namespace darkroom::ssdof {
namespace HWY_NAMESPACE {

void DiscRow(const WorkImage& w, const SpiralPoint* spiral, int samples, int y, const Output& out) {
    const DF d;
    const DI di;
    const int lanes = int(hn::Lanes(d));
    const VF zero = hn::Zero(d), focus = hn::Set(d, kInFocus);
    const float perSample = 1.0f / float(samples);
    const auto stride = hn::Set(di, w.stride);
    for (int x0 = 0; x0 < w.width; x0 += lanes) {
        const int count = std::min(lanes, w.width - x0);
        const std::size_t i = w.index(x0, y);
        const MF inImage = hn::FirstN(d, std::size_t(count));
        const VF sp = hn::IfThenElseZero(inImage, hn::LoadU(d, w.coc.data() + i));  // 0 past the image's edge
        const VF rp = hn::Abs(sp);
        const VF self[4] = {hn::LoadU(d, w.r.data() + i), hn::LoadU(d, w.g.data() + i), hn::LoadU(d, w.b.data() + i),
                            hn::LoadU(d, w.a.data() + i)};

        // Near layer: spiral over the largest near CoC that can reach this tile.
        Layer nearL = Layer::zero();
        const float reach = w.reachAt(x0, y);
        if (reach >= kInFocus) {
            // Spiral point area over the sample's kernel area: a near region
            // of uniform CoC = reach sums to exactly 1.
            const VF area = hn::Set(d, reach * reach * perSample);
            for (int s = 0; s < samples; ++s) {
                const SpiralPoint& o = spiral[s];
                const int dx = int(std::lround(o.x * reach)), dy = int(std::lround(o.y * reach));
                const std::size_t j = w.index(x0 + dx, y + dy);
                const VF sq = hn::LoadU(d, w.coc.data() + j);
                const VF t = hn::Set(d, std::sqrt(float(dx * dx + dy * dy)));
                const MF reaches = hn::And(hn::Not(hn::IsNaN(sq)), ReachesAsNear(sp, sq, t));
                const VF wq = hn::IfThenElseZero(reaches, hn::Div(area, hn::Mul(sq, sq)));
                nearL.add(wq, hn::LoadU(d, w.r.data() + j), hn::LoadU(d, w.g.data() + j), hn::LoadU(d, w.b.data() + j),
                          hn::LoadU(d, w.a.data() + j));
            }
        }
        const MF unchanged = hn::And(hn::Lt(rp, focus), hn::Eq(nearL.weight, zero));
        const std::size_t o = std::size_t(y) * std::size_t(w.width) + std::size_t(x0);
        if (hn::AllTrue(d, hn::Or(unchanged, hn::Not(inImage)))) {
            Finish(out, o, count, nearL, Layer::zero(), self[0], self[1], self[2], self[3], unchanged);
            continue;
        }

        // Focus/far layer over the pixel's own CoC; the pixel itself counts
        // unless it is in the near field (then this layer is what lies behind it).
        Layer backL = Layer::zero();
        const VF cc = hn::Max(rp, focus);
        backL.add(hn::IfThenElseZero(hn::Gt(sp, hn::Neg(focus)), hn::Div(hn::Set(d, 1.0f), hn::Mul(cc, cc))), self[0], self[1],
                  self[2], self[3]);
        const MF blurred = hn::Ge(rp, focus);
        if (!hn::AllFalse(d, blurred)) {
            const VI here = hn::Add(hn::Set(di, int(i)), hn::Iota(di, 0));
            for (int s = 0; s < samples; ++s) {
                const VF ox = hn::Mul(hn::Set(d, spiral[s].x), rp), oy = hn::Mul(hn::Set(d, spiral[s].y), rp);
                const VI dx = hn::ConvertTo(di, RoundHalfAway(ox)), dy = hn::ConvertTo(di, RoundHalfAway(oy));
                const VI j = hn::Add(here, hn::Add(dx, hn::Mul(dy, stride)));
                const VF sq = hn::GatherIndex(d, w.coc.data(), j);
                const VF t = hn::Sqrt(hn::ConvertTo(d, hn::Add(hn::Mul(dx, dx), hn::Mul(dy, dy))));
                const MF use = hn::And(blurred, hn::Not(hn::IsNaN(sq)));
                const VF wq = hn::IfThenElseZero(use, BackgroundWeight(sp, rp, hn::IfThenElseZero(use, sq), t));
                if (hn::AllFalse(d, hn::Gt(wq, zero))) continue;
                backL.add(wq, hn::GatherIndex(d, w.r.data(), j), hn::GatherIndex(d, w.g.data(), j),
                          hn::GatherIndex(d, w.b.data(), j), hn::GatherIndex(d, w.a.data(), j));
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
HWY_EXPORT(DiscRow);

namespace {

// Vogel's spiral: point i at radius sqrt((i + 0.5) / n) and angle i * golden
// angle covers the disc with equal area per point, so each represents pi r^2 / n.
std::vector<SpiralPoint> vogelSpiral(int n) {
    const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
    std::vector<SpiralPoint> s(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        const double r = std::sqrt((i + 0.5) / n), a = i * golden;
        s[std::size_t(i)] = {float(r * std::cos(a)), float(r * std::sin(a))};
    }
    return s;
}

}  // namespace

void gatherDisc(const WorkImage& w, int samples, Context& ctx, const Output& out) {
    const auto spiral = vogelSpiral(samples);
    ctx.parallelFor(0, w.height, 4, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) HWY_DYNAMIC_DISPATCH(DiscRow)(w, spiral.data(), samples, y, out);
    });
}

}  // namespace darkroom::ssdof
#endif
