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
// The rules in code are in layer_rules-inl.h.
#include <cstddef>
#include <memory>
#include <vector>

namespace darkroom {
class Context;
class WritableBuffer;
}

namespace darkroom::ssdof {

struct LensModel;

// CoC below this radius (pixels) is in focus: such a pixel neither scatters
// nor is blurred; with no near-field light on it, it is copied exactly.
constexpr float kInFocus = 0.5f;
// Samples whose CoC differs by less than this (pixels) are on the same layer.
constexpr float kSameLayer = 1.0f;
// Near-field reach is tracked per square tile of this many pixels.
constexpr int kTile = 16;

// Planes of the image with a border of `pad` pixels on every side (CoC NaN,
// colour 0 there) so that a tap never leaves the planes: a tap outside the
// image is one whose CoC is NaN.
struct WorkImage {
    // One padded plane (in `storage`, from the host's pool).
    struct Plane {
        float* values = nullptr;
        float* data() const { return values; }
    };
    int width = 0, height = 0;
    int pad = 0;     // at least the largest tap offset of either gather
    int stride = 0;  // floats per padded row (room for a vector past the right border)
    Plane r, g, b, a;  // premultiplied colour, non-finite components replaced by 0
    Plane coc;         // signed CoC radius, pixels
    std::shared_ptr<WritableBuffer> storage;
    std::vector<float> nearReach;   // per tile: largest near-field |CoC| that can reach it
    int tilesX = 0;

    std::size_t index(int x, int y) const {
        return std::size_t(y + pad) * std::size_t(stride) + std::size_t(x + pad);
    }
    float reachAt(int x, int y) const {
        return nearReach[std::size_t(y / kTile) * std::size_t(tilesX) + std::size_t(x / kTile)];
    }
};

// Fills `w` from the input planes (A may be null: opaque) with the CoC of
// `lens`, padded for CoCs up to lens.maxBlur. Returns whether any pixel is
// out of focus.
bool buildWorkImage(Context& ctx, const float* const rgba[4], const float* z, int width, int height,
                    const LensModel& lens, WorkImage& w);

// Fills WorkImage::nearReach from WorkImage::coc (dilated by the largest reach).
void computeNearReach(WorkImage& w);

// Where the gathers write: straight (un-premultiplied) colour, or the input's
// own bits where a pixel is in focus with no near-field light on it.
struct Output {
    const float* in[4];  // R, G, B, A of the input (A may be null)
    float* out[4];       // R, G, B, A (A null when the input has none)
};

}  // namespace darkroom::ssdof
