#pragma once
// Which spans of a row of floats are all background for an 8-bit encoder:
// no value above zero (NaN, zeros and negatives all give code 0). SIMD
// (Highway, the best target the CPU has), for eight_bit.cpp.
#include <cstddef>
#include <cstdint>

namespace darkroom::io {

constexpr std::size_t kBackgroundSpan = 32;

// flags[k] = 1 when s[k * kBackgroundSpan ...] (up to n) holds no value > 0.
void markBackgroundSpans(const float* s, std::size_t n, std::uint8_t* flags);

}  // namespace darkroom::io
