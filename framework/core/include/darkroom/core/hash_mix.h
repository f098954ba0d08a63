#pragma once
// Mixing 64-bit hashes: the cache keys of the evaluator and the content
// digests databases record (the in situ setup's camera poses). Not meant
// to resist a forger. Header-only, so it adds nothing to any library's ABI.
#include <cstdint>
#include <cstring>
#include <string_view>

namespace darkroom::hashing {

inline std::uint64_t mix(std::uint64_t h, std::uint64_t v) {
    // splitmix64 finaliser over the running hash: cheap and well distributed.
    std::uint64_t z = h ^ (v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2));
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

inline std::uint64_t mixText(std::uint64_t h, std::string_view s) {
    h = mix(h, s.size());
    std::size_t i = 0;
    for (; i + 8 <= s.size(); i += 8) {
        std::uint64_t w;
        std::memcpy(&w, s.data() + i, 8);
        h = mix(h, w);
    }
    std::uint64_t tail = 0;
    std::memcpy(&tail, s.data() + i, s.size() - i);
    return mix(h, tail);
}

inline std::uint64_t mixDouble(std::uint64_t h, double d) {
    std::uint64_t w;
    std::memcpy(&w, &d, 8);
    return mix(h, w);
}

}  // namespace darkroom::hashing
