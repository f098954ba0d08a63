// The working image of the gathers: premultiplied colour and signed CoC in
// padded planes, and the near-field reach per tile. A vector of pixels at a
// time; the CoC in double precision as LensModel::signedRadius computes it.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/work_image.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "coc.h"
#include "layers.h"

#include <darkroom/buffer.h>
#include <darkroom/context.h>

#include <algorithm>
#include <cmath>
#include <limits>

HWY_BEFORE_NAMESPACE();
namespace darkroom::ssdof {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Row y of the work image; returns whether some pixel of it is out of focus.
bool BuildRow(const float* const rgba[4], const float* z, int width, const LensModel& lens, const WorkImage& w,
              float* const planes[5], int y) {
    const hn::ScalableTag<double> d;
    const hn::Rebind<float, decltype(d)> df;
    const int lanes = int(hn::Lanes(d));
    const bool lensOk = lens.aperture > 0.0 && lens.pixelPerDepth > 0.0;
    const double k = lens.aperture / (2.0 * lens.pixelPerDepth);
    const double invF = std::isfinite(lens.focalDistance) ? 1.0 / lens.focalDistance : 0.0;
    const double focalOr1 = std::isfinite(lens.focalDistance) ? lens.focalDistance : 1.0;
    const auto zero = hn::Zero(d), inf = hn::Set(d, std::numeric_limits<double>::infinity());
    const auto fzero = hn::Zero(df), fone = hn::Set(df, 1.0f), finf = hn::Set(df, std::numeric_limits<float>::infinity());
    auto finite = [&](auto v) { return hn::Lt(hn::Abs(v), finf); };
    bool anyBlur = false;
    const std::size_t row = std::size_t(y) * std::size_t(width);
    auto pixels = [&](int x) {
        const std::size_t i = row + std::size_t(x), o = w.index(x, y);
        // LensModel::signedRadius.
        const auto zd = hn::PromoteTo(d, hn::LoadU(df, z + i));
        const auto invZ = hn::IfThenElseZero(hn::And(hn::Gt(zd, zero), hn::Lt(zd, inf)), hn::Div(hn::Set(d, 1.0), zd));
        auto r = hn::Mul(hn::Set(d, k), hn::Sub(hn::Set(d, invF), invZ));
        if (lens.orthographic) r = hn::Mul(r, hn::Set(d, focalOr1));
        const auto lo = hn::Set(d, -lens.maxBlur), hi = hn::Set(d, lens.maxBlur);
        r = hn::IfThenElse(hn::Lt(r, lo), lo, hn::IfThenElse(hn::Lt(hi, r), hi, r));
        r = hn::IfThenElseZero(hn::Not(hn::IsNaN(r)), r);
        const auto coc = lensOk ? hn::DemoteTo(df, r) : fzero;
        hn::StoreU(coc, df, planes[4] + o);
        anyBlur = anyBlur || !hn::AllFalse(df, hn::Ge(hn::Abs(coc), hn::Set(df, kInFocus)));
        // Premultiplied; a non-finite component (NaN colour on background) carries no light.
        auto a = fone;
        if (rgba[3]) {
            const auto in = hn::LoadU(df, rgba[3] + i);
            a = hn::IfThenElseZero(finite(in), in);
        }
        for (int c = 0; c < 3; ++c) {
            const auto v = hn::LoadU(df, rgba[c] + i);
            hn::StoreU(hn::IfThenElseZero(finite(v), hn::Mul(v, a)), df, planes[c] + o);
        }
        hn::StoreU(a, df, planes[3] + o);
    };
    if (width < lanes) {
        // Too narrow for a vector: the pixels one by one, as the vectors do them.
        for (int x = 0; x < width; ++x) {
            const std::size_t i = row + std::size_t(x), o = w.index(x, y);
            planes[4][o] = lens.signedRadius(z[i]);
            anyBlur = anyBlur || std::fabs(planes[4][o]) >= kInFocus;
            const float a = rgba[3] ? (std::isfinite(rgba[3][i]) ? rgba[3][i] : 0.0f) : 1.0f;
            for (int c = 0; c < 3; ++c) planes[c][o] = std::isfinite(rgba[c][i]) ? rgba[c][i] * a : 0.0f;
            planes[3][o] = a;
        }
        return anyBlur;
    }
    for (int x = 0;; x += lanes) {
        if (x + lanes > width) x = width - lanes;  // overlap the last vector: pixels are independent
        pixels(x);
        if (x + lanes == width) break;
    }
    return anyBlur;
}

// The largest near-field |CoC| of each tile's pixels of row y (0 where none).
void RowNearReach(const WorkImage& w, int y, float* tileMax) {
    const hn::ScalableTag<float> d;
    const int lanes = int(hn::Lanes(d));
    const auto focus = hn::Set(d, -kInFocus);
    const float* coc = w.coc.data() + w.index(0, y);
    for (int tx = 0; tx < w.tilesX; ++tx) {
        auto m = hn::Zero(d);
        const int x0 = tx * kTile, x1 = std::min(x0 + kTile, w.width);
        int x = x0;
        for (; x + lanes <= x1; x += lanes) {
            const auto s = hn::LoadU(d, coc + x);
            m = hn::Max(m, hn::IfThenElseZero(hn::Le(s, focus), hn::Neg(s)));
        }
        float t = hn::GetLane(hn::MaxOfLanes(d, m));
        for (; x < x1; ++x)
            if (coc[x] <= -kInFocus) t = std::max(t, -coc[x]);
        tileMax[tx] = std::max(tileMax[tx], t);
    }
}

}  // namespace HWY_NAMESPACE
}  // namespace darkroom::ssdof
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace darkroom::ssdof {
HWY_EXPORT(BuildRow);
HWY_EXPORT(RowNearReach);

bool buildWorkImage(Context& ctx, const float* const rgba[4], const float* z, int width, int height, const LensModel& lens,
                    WorkImage& w) {
    w.width = width;
    w.height = height;
    // Both gathers' taps stay within round(maxBlur) + 1 pixels; a vector may run
    // 16 floats past the right border.
    w.pad = int(std::ceil(std::min(lens.maxBlur, 1e6))) + 2;
    w.stride = width + 2 * w.pad + 16;
    // Planes from the host's pool (no page faults when the pass runs again);
    // the image's pixels are all written below, the padding here: colour 0,
    // CoC NaN (outside the image).
    w.storage = ctx.allocate(w.stride, height + 2 * w.pad, {"R", "G", "B", "A", "CoC"}, Fill::None);
    WorkImage::Plane* views[5] = {&w.r, &w.g, &w.b, &w.a, &w.coc};
    const char* names[5] = {"R", "G", "B", "A", "CoC"};
    float* planes[5];
    for (int c = 0; c < 5; ++c) planes[c] = views[c]->values = w.storage->writeFloat(names[c]);
    const std::size_t rowFloats = std::size_t(w.stride);
    ctx.parallelFor(0, height + 2 * w.pad, 64, [&](int y0, int y1) {
        for (int c = 0; c < 5; ++c) {
            const float outside = c == 4 ? std::numeric_limits<float>::quiet_NaN() : 0.0f;
            for (int y = y0; y < y1; ++y) {
                float* row = planes[c] + std::size_t(y) * rowFloats;
                if (y < w.pad || y >= w.pad + height) {
                    std::fill(row, row + rowFloats, outside);
                } else {
                    std::fill(row, row + w.pad, outside);
                    std::fill(row + w.pad + width, row + rowFloats, outside);
                }
            }
        }
    });
    bool anyBlur = false;
    std::vector<char> rowBlur(std::size_t(height), 0);
    ctx.parallelFor(0, height, 16, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) rowBlur[std::size_t(y)] = HWY_DYNAMIC_DISPATCH(BuildRow)(rgba, z, width, lens, w, planes, y);
    });
    for (char b : rowBlur) anyBlur = anyBlur || b;
    return anyBlur;
}

void computeNearReach(WorkImage& w) {
    w.tilesX = (w.width + kTile - 1) / kTile;
    const int tilesY = (w.height + kTile - 1) / kTile;
    std::vector<float> own(std::size_t(w.tilesX) * std::size_t(tilesY), 0.0f);
    for (int y = 0; y < w.height; ++y)
        HWY_DYNAMIC_DISPATCH(RowNearReach)(w, y, own.data() + std::size_t(y / kTile) * std::size_t(w.tilesX));
    const float largest = own.empty() ? 0.0f : *std::max_element(own.begin(), own.end());
    // A near pixel reaches at most |s| + 1 pixels, so tiles farther than that
    // (in whole tiles) cannot see it.
    const int k = int(std::ceil((largest + 1.0f) / float(kTile)));
    w.nearReach.assign(own.size(), 0.0f);
    for (int ty = 0; ty < tilesY; ++ty)
        for (int tx = 0; tx < w.tilesX; ++tx) {
            float m = 0.0f;
            for (int y = std::max(0, ty - k); y <= std::min(tilesY - 1, ty + k); ++y)
                for (int x = std::max(0, tx - k); x <= std::min(w.tilesX - 1, tx + k); ++x)
                    m = std::max(m, own[std::size_t(y) * std::size_t(w.tilesX) + std::size_t(x)]);
            w.nearReach[std::size_t(ty) * std::size_t(w.tilesX) + std::size_t(tx)] = m;
        }
}

}  // namespace darkroom::ssdof
#endif
