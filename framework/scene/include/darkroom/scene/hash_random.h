#pragma once
// Counter-based random numbers: value = hash(seed, index, stream). Results do
// not depend on call order or thread count, unlike a shared generator.
#include <cstdint>

namespace darkroom::generators {

inline std::uint64_t mix64(std::uint64_t z) {  // SplitMix64 finaliser
    z += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

// Uniform in [0, 1).
inline double hashUniform(std::uint64_t seed, std::uint64_t index, std::uint64_t stream) {
    const std::uint64_t h = mix64(mix64(mix64(seed) ^ index) ^ (stream * 0x632be59bd9b4e019ull));
    return static_cast<double>(h >> 11) * (1.0 / 9007199254740992.0);
}

}  // namespace darkroom::generators
