#pragma once
// Separable Gaussian blur of depth that ignores pixels without a surface
// (normalised convolution): background never contributes an infinity, and
// pixels near the background or the image border average only the surface
// they can see.
#include <darkroom/context.h>

#include <vector>

namespace darkroom::passes {

// Blurred depth for every pixel, NaN where the pixel itself has no surface.
// sigma in pixels (> 0); the kernel is truncated at 3 sigma.
std::vector<float> maskedGaussianDepth(Context& ctx, const float* depth, int width, int height,
                                       double sigma);

}  // namespace darkroom::passes
