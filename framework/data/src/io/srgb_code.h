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
#include <bit>
#include <cstdint>

namespace darkroom::io {

// The tables, built once per process (some 24,000 pows); code() is inline
// so that a loop over a whole image looks the tables up once and keeps
// them in registers.
struct SrgbCodeTable {
    static constexpr int kBucketShift = 16;
    const std::uint32_t* threshold;    // [k]: bits of the least float whose code is >= k; [256]: 1.0f
    const std::uint8_t* bucketStart;   // the code of the first float of each bucket of 2^16 floats
    const std::uint32_t* bucketStartWide;  // the same codes as 32-bit words, for SIMD gathers (eight_bit_rows.cpp)

    // v must be in (0, 1): callers map NaN, v <= 0 and v >= 1 themselves.
    std::uint8_t code(float v) const {
        const std::uint32_t bits = std::bit_cast<std::uint32_t>(v);
        unsigned code = bucketStart[bits >> kBucketShift];
        while (bits >= threshold[code + 1]) ++code;
        return std::uint8_t(code);
    }
};

const SrgbCodeTable& srgbCodeTable();

// v must be in (0, 1), as for SrgbCodeTable::code.
inline std::uint8_t srgbCode(float v) { return srgbCodeTable().code(v); }

}  // namespace darkroom::io
