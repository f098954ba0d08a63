#include "fxaa_kernel.h"

#include <algorithm>
#include <cmath>

namespace darkroom::fxaa {

namespace {

// Luma reads around one centre pixel: clamped to the image, NaN -> centre.
class Reader {
public:
    Reader(const LumaPlane& p, float centre) : p_(p), centre_(centre) {}

    float at(int x, int y) const {
        x = std::clamp(x, 0, p_.width - 1);
        y = std::clamp(y, 0, p_.height - 1);
        const float v = p_.luma[std::size_t(y) * std::size_t(p_.width) + std::size_t(x)];
        return std::isnan(v) ? centre_ : v;
    }

    // FXAA's search fetch: a bilinear sample half way between the centre's
    // line and the neighbour's line (weights 1/2, 1/2 across the edge) at a
    // fractional position `t` along the edge. `horizontal` edges run along x.
    float edgeSample(bool horizontal, int x, int y, int side, float t) const {
        const int i0 = int(std::floor(t));
        const float f = t - float(i0);
        float a, b;
        if (horizontal) {
            a = at(i0, y) + at(i0, y + side);
            b = at(i0 + 1, y) + at(i0 + 1, y + side);
        } else {
            a = at(x, i0) + at(x + side, i0);
            b = at(x, i0 + 1) + at(x + side, i0 + 1);
        }
        return 0.5f * (a + f * (b - a));
    }

private:
    const LumaPlane& p_;
    float centre_;
};

struct SearchEnd {
    float distance;  // pixels from the centre to where the search stopped
    float luma;      // the last sample minus the average luma of the edge pair
};

// Walks along the edge in direction `dir` (+-1) with the preset's steps until
// the luma of the edge pair changes by at least a quarter of the gradient
// across the edge: that is where the edge ends.
SearchEnd searchEdgeEnd(const Reader& r, bool horizontal, int x, int y, int side, int dir,
                        float pairAverage, float gradientQuarter, const Preset& preset) {
    const float origin = horizontal ? float(x) : float(y);
    const auto& steps = preset.steps;
    float distance = steps[0];
    float luma = 0.0f;
    for (std::size_t k = 1;; ++k) {
        luma = r.edgeSample(horizontal, x, y, side, origin + float(dir) * distance) - pairAverage;
        if (std::fabs(luma) >= gradientQuarter) break;
        distance += steps[k];
        // The last step is taken without a sample after it: FXAA's guess that
        // the edge goes on beyond the searched span.
        if (k + 1 == steps.size()) break;
    }
    return {distance, luma};
}

}  // namespace

Blend decide(const LumaPlane& plane, int x, int y, const Settings& s) {
    const float m = plane.luma[std::size_t(y) * std::size_t(plane.width) + std::size_t(x)];
    const Reader r(plane, m);

    // 1. Local contrast on the cross: too little -> not an edge, keep the pixel.
    const float n = r.at(x, y - 1), so = r.at(x, y + 1), e = r.at(x + 1, y), w = r.at(x - 1, y);
    const float rangeMax = std::max({m, n, so, e, w});
    const float rangeMin = std::min({m, n, so, e, w});
    const float range = rangeMax - rangeMin;
    if (range < std::max(s.edgeThresholdMin, rangeMax * s.edgeThreshold) || !(range > 0.0f)) return {};

    // 2. Edge orientation: second differences across x and y over the 3x3
    // block, the centre line weighted twice.
    const float nw = r.at(x - 1, y - 1), ne = r.at(x + 1, y - 1);
    const float sw = r.at(x - 1, y + 1), se = r.at(x + 1, y + 1);
    const float edgeHorizontal = std::fabs(nw + sw - 2.0f * w) + 2.0f * std::fabs(n + so - 2.0f * m) +
                                 std::fabs(ne + se - 2.0f * e);
    const float edgeVertical = std::fabs(nw + ne - 2.0f * n) + 2.0f * std::fabs(w + e - 2.0f * m) +
                               std::fabs(sw + se - 2.0f * so);
    const bool horizontal = edgeHorizontal >= edgeVertical;

    // 3. Sub-pixel aliasing: how far the centre stands out of the 3x3 low-pass
    // (cross weighted 2, corners 1), relative to the local range, through a
    // smoothstep and squared.
    const float lowPass = (2.0f * (n + so + w + e) + (nw + ne + sw + se)) * (1.0f / 12.0f);
    const float subpixC = std::clamp(std::fabs(lowPass - m) / range, 0.0f, 1.0f);
    const float subpixF = subpixC * subpixC * (3.0f - 2.0f * subpixC);
    const float subpixBlend = subpixF * subpixF * s.subpix;

    // 4. Across the edge, the side with the steeper gradient is the one to
    // blend with; the edge pair is (centre, that neighbour).
    const float before = horizontal ? n : w;  // -1 side
    const float after = horizontal ? so : e;  // +1 side
    const float gradBefore = before - m, gradAfter = after - m;
    const bool towardsBefore = std::fabs(gradBefore) >= std::fabs(gradAfter);
    const int side = towardsBefore ? -1 : 1;
    const float gradient = std::max(std::fabs(gradBefore), std::fabs(gradAfter));
    const float pairAverage = 0.5f * (m + (towardsBefore ? before : after));
    const float gradientQuarter = 0.25f * gradient;
    const bool centreBelowPair = m - pairAverage < 0.0f;

    // 5. Search both ways along the edge for its ends.
    const SearchEnd neg = searchEdgeEnd(r, horizontal, x, y, side, -1, pairAverage, gradientQuarter, *s.preset);
    const SearchEnd pos = searchEdgeEnd(r, horizontal, x, y, side, +1, pairAverage, gradientQuarter, *s.preset);

    // 6. The nearer end decides. The blend is right only if the luma there
    // moves the other way from the centre (the edge "turns" towards this
    // pixel's side: the step of a staircase); then the pixel takes
    // 1/2 - distance/length of its neighbour, a linear ramp along the edge.
    const bool negNearer = neg.distance < pos.distance;
    const float nearest = std::min(neg.distance, pos.distance);
    const bool goodSpan = ((negNearer ? neg.luma : pos.luma) < 0.0f) != centreBelowPair;
    const float edgeBlend = goodSpan ? 0.5f - nearest / (neg.distance + pos.distance) : 0.0f;

    Blend b;
    b.amount = std::clamp(std::max(edgeBlend, subpixBlend), 0.0f, 1.0f);
    if (horizontal)
        b.dy = side;
    else
        b.dx = side;
    return b;
}

}  // namespace darkroom::fxaa
