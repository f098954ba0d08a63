#pragma once
// What both gathers share: the premultiplied working image, the signed CoC
// map, the near-field reach per tile, and the rules that decide which sample
// reaches which pixel (scatter-as-gather with two layers).
//
// The model: every pixel q is a point whose light the lens spreads over a
// disc (or hexagon) of radius |s_q| pixels, s_q the signed CoC (< 0 in front
// of the focal plane). Output pixel p is composited from two layers:
//   near layer F  — samples in the near field (s_q <= -0.5) whose own CoC
//                    reaches p, each weighted by 1 / (its kernel area), so a
//                    uniform near region sums to coverage 1 and a lone near
//                    point spreads its energy over its kernel. Coverage
//                    alpha_F = min(1, sum of weights); colour = weighted mean.
//   focus/far layer B — samples not in front of p (s_q >= s_p - tau) whose
//                    CoC, limited to p's own (min(|s_q|, |s_p|)), reaches p:
//                    far samples do not bleed over nearer sharp pixels, and
//                    an in-focus pixel keeps only itself. For a near pixel p
//                    the layer stands for what lies behind it: the samples
//                    behind p within |s_p| (visible background around the
//                    near object), or p itself when there are none.
// out = alpha_F * F + (1 - alpha_F) * B, in premultiplied RGBA.
#include <cmath>
#include <cstddef>
#include <vector>

namespace darkroom::ssdof {

// CoC below this radius (pixels) is in focus: such a pixel neither scatters
// nor is blurred; with no near-field light on it, it is copied exactly.
constexpr float kInFocus = 0.5f;
// Samples whose CoC differs by less than this (pixels) are on the same layer.
constexpr float kSameLayer = 1.0f;
// Near-field reach is tracked per square tile of this many pixels.
constexpr int kTile = 16;

struct Rgba {
    float r = 0, g = 0, b = 0, a = 0;
    void add(const Rgba& c, float w) {
        r += w * c.r;
        g += w * c.g;
        b += w * c.b;
        a += w * c.a;
    }
};

struct WorkImage {
    int width = 0, height = 0;
    std::vector<Rgba> colour;  // premultiplied, non-finite components replaced by 0
    std::vector<float> coc;    // signed CoC radius, pixels
    std::vector<float> nearReach;  // per tile: largest near-field |CoC| that can reach it
    int tilesX = 0;

    std::size_t index(int x, int y) const { return std::size_t(y) * std::size_t(width) + std::size_t(x); }
    float reachAt(int x, int y) const { return nearReach[std::size_t(y / kTile) * std::size_t(tilesX) + std::size_t(x / kTile)]; }
};

// Fills WorkImage::nearReach from WorkImage::coc (dilated by the largest reach).
void computeNearReach(WorkImage& w);

// Does sample q (signed CoC sq) at distance t contribute to the focus/far
// layer of p (signed CoC sp)? Returns its weight, 0 when it does not.
inline float backgroundWeight(float sp, float sq, float t) {
    const float rp = std::fabs(sp);
    if (sp <= -kInFocus) {  // p in the near field: what lies behind it
        return (sq > sp + kSameLayer && t <= rp + 0.5f) ? 1.0f : 0.0f;
    }
    if (sq < sp - kSameLayer) return 0.0f;  // in front of p: belongs to the near layer or is hidden
    const float c = std::fmin(std::fabs(sq), rp);
    if (t > c + 0.5f) return 0.0f;
    const float cc = std::fmax(c, kInFocus);
    return 1.0f / (cc * cc);
}

// Does sample q reach p through the near layer? sp only excludes near samples
// behind a nearer p. Returns true; the caller applies its kernel-area weight.
inline bool reachesAsNear(float sp, float sq, float t) {
    if (sq > -kInFocus) return false;
    if (sp <= -kInFocus && sq > sp + kSameLayer) return false;
    return t <= -sq + 0.5f;
}

// Composites the layers and writes straight (un-premultiplied) RGBA.
inline Rgba composite(const Rgba& nearSum, float nearWeight, float nearAlpha, const Rgba& backSum,
                      float backWeight, const Rgba& self) {
    Rgba out;
    const float a = std::fmin(nearAlpha, 1.0f);
    if (a > 0.0f) out.add(nearSum, a / nearWeight);
    if (backWeight > 0.0f)
        out.add(backSum, (1.0f - a) / backWeight);
    else
        out.add(self, 1.0f - a);
    return out;
}

}  // namespace darkroom::ssdof
