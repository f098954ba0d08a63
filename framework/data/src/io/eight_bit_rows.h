#pragma once
// One row of float channels as interleaved 8-bit codes, a vector of pixels
// at a time (Highway, the best target the CPU has): colour channels through
// the sRGB code table (srgb_code.h), the alpha channel linearly. The same
// bytes as eight_bit.h's per-value rules (encodeColourValue,
// encodeAlphaValue), which the tests compare it with. For eight_bit.cpp.
#include <cstddef>

namespace darkroom::io {

// planes[c] + 0 .. width - 1 for c < channels (1 to 4); the last one is
// alpha when `alpha`. Writes width * channels bytes at `out`.
void encodeEightBitRow(const float* const* planes, int channels, bool alpha, std::size_t width, unsigned char* out);

}  // namespace darkroom::io
