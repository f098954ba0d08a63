#pragma once
// Whether two planes hold the same bytes, answered cheaply when they do not.
// The evaluator compares every fresh image plane with the one it replaces
// (keepUnchangedPlanes) so that an unchanged plane keeps downstream caches.
// Between the entries of a batch the planes nearly always differ, but a
// plain memcmp finds that only at the first difference, often after many
// equal rows of background (3 % of a --foreach run's CPU at 2048²). Probes
// spread over the plane find most differences in a few cache lines: one
// every 1/1024 of the plane (every 4 rows at 2048²), dense enough that a
// picture that is mostly background still has its geometry probed (64
// probes were not: 84 % of the demo's 2048² isosurface is background).
// Only planes equal at every probe are compared in full.
#include <cstddef>
#include <cstring>

namespace darkroom {

// Whether the probes alone show that a and b differ (false: they may
// still differ between the probes). Planes under 256 KiB are not probed.
inline bool probesDiffer(const void* a, const void* b, std::size_t bytes) {
    constexpr std::size_t kProbes = 1024, kProbeBytes = 64;
    if (bytes < kProbes * kProbeBytes * 4) return false;
    const auto* pa = static_cast<const unsigned char*>(a);
    const auto* pb = static_cast<const unsigned char*>(b);
    const std::size_t stride = bytes / kProbes;
    for (std::size_t k = 0; k < kProbes; ++k) {
        // Somewhere else in each stretch (a multiplicative hash of k): at a
        // fixed place in each, with stretches a whole number of rows long,
        // every probe would fall in the same columns, the picture's edge or
        // its background.
        const std::size_t at = k * stride + std::size_t((k * 0x9E3779B97F4A7C15ull) >> 40) % (stride - kProbeBytes);
        if (std::memcmp(pa + at, pb + at, kProbeBytes) != 0) return true;
    }
    return false;
}

inline bool sameBytes(const void* a, const void* b, std::size_t bytes) {
    return !probesDiffer(a, b, bytes) && std::memcmp(a, b, bytes) == 0;
}

}  // namespace darkroom
