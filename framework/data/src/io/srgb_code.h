#pragma once
// Linear light in (0, 1) -> 8-bit sRGB code value, exactly
// lround(linearToSrgb(v) * 255) (darkroom/srgb.h) without its pow per value,
// which cost more than deflating the PNG (docs/performance.md, Codecs).
//
// The code only grows with v, so it is fixed by 255 thresholds: the least
// float giving each code, found once by bisection over the float bit
// patterns of the very function it replaces. A value's top 16 bits pick the
// code at the start of its bucket; at most a few thresholds lie inside one
// bucket, stepped over by comparison. Same bits as the pow, by construction
// (and tested against it, tests/unit/io/srgb_code_test.cpp).
#include <cstdint>

namespace darkroom::io {

// v must be in (0, 1): callers map NaN, v <= 0 and v >= 1 themselves.
std::uint8_t srgbCode(float v);

}  // namespace darkroom::io
