#pragma once
// Per-pixel deterministic noise: a hash of (x, y, seed, stream), so results do
// not depend on the thread count or on the order pixels are visited.
#include <cstdint>

namespace darkroom::ssao {

// A 32-bit integer finaliser (the "lowbias32" constants of Chris Wellons'
// hash prospector), good avalanche for sequential inputs.
inline std::uint32_t mix32(std::uint32_t v) {
    v ^= v >> 16;
    v *= 0x7feb352dU;
    v ^= v >> 15;
    v *= 0x846ca68bU;
    v ^= v >> 16;
    return v;
}

// Uniform in [0, 1) for pixel (x, y), a user seed and a stream index.
inline float pixelNoise(int x, int y, std::uint32_t seed, std::uint32_t stream) {
    std::uint32_t h = mix32(std::uint32_t(x) * 0x9e3779b9U ^ mix32(std::uint32_t(y) + 0x632be5abU));
    h = mix32(h ^ mix32(seed * 0x85ebca6bU + stream));
    return float(h >> 8) * (1.0f / 16777216.0f);
}

}  // namespace darkroom::ssao
