#pragma once
// Depth-aware (bilateral) blur that removes the per-pixel noise pattern of the
// estimators without bleeding occlusion across depth edges.
#include "ao_estimators.h"
#include "pixel_geometry.h"

#include <darkroom/context.h>

namespace darkroom::ssao {

// Separable: a horizontal then a vertical pass of 2*radius+1 taps. A tap's
// weight is a Gaussian in pixels (sigma = radius / 2) times a Gaussian in its
// distance from the centre pixel's tangent plane (sigma = 10 % of the
// occlusion radius), so only neighbours on the same surface mix. Pixels
// without valid depth are neither read nor changed.
void bilateralBlur(const PixelGeometry& g, const AoSettings& s, int radius, Context& ctx, float* ao);

}  // namespace darkroom::ssao
