#pragma once
// Deterministic sampling for the references: every random number is a hash
// of (pixel, sample, seed, dimension), so results do not depend on the thread
// count or on the order in which pixels are processed.
#include <darkroom/math.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace darkroom::reference::detail {

inline constexpr double kPi = 3.14159265358979323846;

// SplitMix64's finaliser (Steele, Lea, Flood 2014): a bijective mix with good
// avalanche, enough for Monte Carlo sample positions.
inline std::uint64_t mix64(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

// A uniform number in [0, 1) for (pixel, sample, seed, dimension).
inline double uniform(std::uint64_t pixel, std::uint32_t sample, std::uint32_t seed, std::uint32_t dim) {
    const std::uint64_t key = mix64(pixel * 0x9E3779B97F4A7C15ull + (std::uint64_t(seed) << 32 | dim)) ^
                              (std::uint64_t(sample) * 0xD1B54A32D192ED03ull);
    return double(mix64(key) >> 11) * (1.0 / 9007199254740992.0);  // 53 bits
}

// Orthonormal tangents of unit n (Frisvad's construction, made robust near
// n.z = -1 by Duff et al. 2017).
inline void tangents(const Vec3& n, Vec3& t, Vec3& b) {
    const double s = std::copysign(1.0, n.z);
    const double a = -1.0 / (s + n.z);
    const double c = n.x * n.y * a;
    t = {1.0 + s * n.x * n.x * a, s * c, -s * n.x};
    b = {c, s + n.y * n.y * a, -n.y};
}

// Directions on the hemisphere around +z: cosine-weighted (pdf cos/pi,
// Malley's method) or uniform (pdf 1/2pi).
inline Vec3 cosineHemisphere(double u1, double u2) {
    const double r = std::sqrt(u1), phi = 2.0 * kPi * u2;
    return {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1.0 - u1))};
}

inline Vec3 uniformHemisphere(double u1, double u2) {
    const double z = u1, r = std::sqrt(std::max(0.0, 1.0 - z * z)), phi = 2.0 * kPi * u2;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

}  // namespace darkroom::reference::detail
