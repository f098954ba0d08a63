#pragma once
// A colour-mapped picture like the demo's output: a shaded, colour-mapped
// disc and a band over a transparent background, 8-bit RGBA, sRGB-encoded,
// with antialiased edges. Deterministic.
#include <vector>

namespace darkroom::bench {

std::vector<unsigned char> colourMappedPicture(int size);

}  // namespace darkroom::bench
