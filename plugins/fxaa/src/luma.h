#pragma once
// The luma FXAA looks at. FXAA expects perceptual luma (its thresholds are
// tuned for gamma-encoded colour), but colour inside the graph is linear, so
// each channel is clamped to [0, 1], sRGB-encoded, and weighted with the
// published Rec. 601 luma weights (0.299, 0.587, 0.114).
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace darkroom::fxaa {

// Perceptual luma of a linear colour. Channels outside [0, 1] (HDR, +inf) are
// clamped first; the result is in [0, 1].
float perceptualLuma(float r, float g, float b);

// Whether a pixel holds colour that may be blended: finite R, G, B and, when
// there is an alpha channel, alpha > 0. NaN colour (no data) and transparent
// pixels (background of a colour-mapped capture) are not.
inline bool blendable(float r, float g, float b, const float* alpha, std::size_t i) {
    if (!std::isfinite(r) || !std::isfinite(g) || !std::isfinite(b)) return false;
    return !alpha || alpha[i] > 0.0f;  // also rejects NaN alpha
}

// The sRGB encoding as a table over s = sqrt(linear), kEncodeEntries + 1
// entries (luma.cpp); for the SIMD luma (fxaa_simd.cpp).
constexpr int kEncodeEntries = 4096;
const float* encodeTable();
// The same table as pairs: entry i holds entries i and i + 1 (the two an
// interpolation reads) as the floats of one 64-bit word, i < kEncodeEntries,
// so that a vector of lookups is one 64-bit gather instead of two 32-bit ones.
const std::uint64_t* encodePairs();

// luma[i] for i in [begin, end): perceptualLuma, or NaN where the pixel is not
// blendable. `alpha` may be null.
void computeLuma(const float* r, const float* g, const float* b, const float* alpha, float* luma,
                 std::size_t begin, std::size_t end);

}  // namespace darkroom::fxaa
