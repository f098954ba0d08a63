// The demo's analytic scalar field (see generators.h). Gradients are analytic
// so the isosurface's winding, the maxima's refinement and the tests agree on
// one exact function instead of finite differences of it.
#include <darkroom/scene/generators.h>

#include <array>
#include <cmath>
#include <numbers>

namespace darkroom::generators {
namespace {

struct Blob {
    Vec3 center;
    double amplitude;
    double sigma;
};

// Strong blobs (amplitude >= 0.8) rise above the default isovalue 0.5; the
// first two overlap into one peanut-shaped surface with two maxima. The weak
// ones (amplitude < 0.5) stay below it: their maxima float outside the surface.
constexpr std::array<Blob, 7> kBlobs{{
    {{-0.38, -0.30, -0.12}, 1.00, 0.24},
    {{0.04, -0.42, -0.32}, 0.90, 0.19},
    {{-0.40, 0.38, 0.30}, 1.00, 0.20},
    {{0.46, -0.32, 0.36}, 0.80, 0.16},
    {{-0.05, 0.02, 0.58}, 0.42, 0.11},
    {{0.50, 0.30, -0.52}, 0.38, 0.11},
    {{-0.58, -0.12, 0.58}, 0.32, 0.10},
}};

// A ring of radius R in a plane tilted about the x axis; strength
// kRingAmp (1 + kRingMod cos 3θ) makes three maxima along it.
constexpr Vec3 kRingCenter{0.32, 0.30, 0.02};
constexpr double kRingRadius = 0.30;
constexpr double kRingSigma = 0.10;
constexpr double kRingAmp = 0.85;
constexpr double kRingMod = 0.20;
// exp(-40) ~ 4e-18: far below any isovalue, so blobs are skipped beyond it,
// which makes sampling far from a blob cheap.
constexpr double kCutoff = 40;

const double kTilt = -0.6;  // radians about x: the ring faces +y and up, towards typical views
const double kCos = std::cos(kTilt), kSin = std::sin(kTilt);

// World -> ring frame (rotation by -tilt about x) and back.
Vec3 toRing(const Vec3& d) { return {d.x, kCos * d.y + kSin * d.z, -kSin * d.y + kCos * d.z}; }
Vec3 fromRing(const Vec3& d) { return {d.x, kCos * d.y - kSin * d.z, kSin * d.y + kCos * d.z}; }

double ringValue(const Vec3& p, Vec3* gradient) {
    const Vec3 q = toRing(p - kRingCenter);
    const double rho = std::sqrt(q.x * q.x + q.y * q.y);
    const double dr = rho - kRingRadius;
    const double s2 = kRingSigma * kRingSigma;
    const double exponent = (dr * dr + q.z * q.z) / (2 * s2);
    if (exponent > kCutoff) {
        if (gradient) *gradient = Vec3{};
        return 0;
    }
    const double e = std::exp(-exponent);
    if (rho < 1e-12) {  // on the axis: the angle is undefined, and e is ~1e-4 here anyway
        if (gradient) *gradient = fromRing({0, 0, -kRingAmp * e * q.z / s2});
        return kRingAmp * e;
    }
    // cos 3θ and sin 3θ from cos θ = x/ρ, sin θ = y/ρ: no atan2 in the hot loop.
    const double c = q.x / rho, s = q.y / rho;
    const double a = kRingAmp * (1 + kRingMod * (4 * c * c * c - 3 * c));
    if (gradient) {
        const double da = -3 * kRingAmp * kRingMod * (3 * s - 4 * s * s * s);  // d a / d theta
        // d/dx: a' θ_x e + a e (-dr ρ_x / s2), ρ_x = x/ρ, θ_x = -y/ρ²; likewise y.
        const double radial = -a * e * dr / s2 / rho;
        const double inv = 1.0 / (rho * rho);
        const Vec3 g{radial * q.x - da * e * q.y * inv, radial * q.y + da * e * q.x * inv, -a * e * q.z / s2};
        *gradient = fromRing(g);
    }
    return a * e;
}

}  // namespace

double demoField(const Vec3& p) {
    double f = ringValue(p, nullptr);
    for (const Blob& b : kBlobs) {
        const Vec3 d = p - b.center;
        const double exponent = dot(d, d) / (2 * b.sigma * b.sigma);
        if (exponent < kCutoff) f += b.amplitude * std::exp(-exponent);
    }
    return f;
}

Vec3 demoFieldGradient(const Vec3& p) {
    Vec3 g;
    ringValue(p, &g);
    for (const Blob& b : kBlobs) {
        const Vec3 d = p - b.center;
        const double s2 = b.sigma * b.sigma;
        const double exponent = dot(d, d) / (2 * s2);
        if (exponent < kCutoff) g = g + d * (-b.amplitude * std::exp(-exponent) / s2);
    }
    return g;
}

Vec3 abcVelocity(const Vec3& p, double a, double b, double c) {
    constexpr double pi = std::numbers::pi;
    const double x = pi * (p.x + 1), y = pi * (p.y + 1), z = pi * (p.z + 1);
    // dp/dt = u(x(p)) / π, because x = π (p + 1).
    return Vec3{a * std::sin(z) + c * std::cos(y), b * std::sin(x) + a * std::cos(z),
                c * std::sin(y) + b * std::cos(x)} *
           (1.0 / pi);
}

}  // namespace darkroom::generators
