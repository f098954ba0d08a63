#pragma once
// Depth-aware (bilateral) blur that removes the per-pixel noise pattern of the
// estimators without bleeding occlusion across depth edges.
#include "ao_estimators.h"
#include "frame.h"

#include <vector>

namespace darkroom::ssao {

// Separable: a horizontal then a vertical pass of 2*radius+1 taps. A tap's
// weight is a Gaussian in pixels (sigma = radius / 2, blurWeights) times a
// Gaussian in its distance from the centre pixel's tangent plane (sigma = 10 %
// of the occlusion radius), so only neighbours on the same surface mix.
// Pixels without valid depth are neither read nor changed. The frame's
// padding must be at least the radius; src's padding must hold finite values.
std::vector<float> blurWeights(int radius);

// Rows [y0, y1) of one pass (horizontal, or vertical) from src into dst,
// both planes of the frame's layout.
void blurRows(const Frame& g, const AoSettings& s, const std::vector<float>& spatial, bool vertical, int y0, int y1,
              const float* src, float* dst);

}  // namespace darkroom::ssao
