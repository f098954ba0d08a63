#include "closed_forms.h"

#include <algorithm>
#include <cmath>

namespace darkroom::listao {

namespace {
constexpr float kPi = 3.14159265358979f;
// A receiver this close to a sphere's surface (relative to its radius) lies
// on it: depth is stored as float, so a point on its own sphere is off by a
// few parts in a million.
constexpr float kOnSurface = 1e-3f;
}  // namespace

float capOcclusion(float cosTheta, float sin2Sigma) {
    if (!(sin2Sigma > 0)) return 0;
    const float s2 = std::min(sin2Sigma, 1.0f);
    const float c = std::clamp(cosTheta, -1.0f, 1.0f);
    // Wholly above (cos theta >= sin sigma) or wholly below the horizon.
    if (c * c >= s2) return c > 0 ? s2 * c : 0.0f;
    const float sinTheta = std::sqrt(1.0f - c * c);
    const float cotSigma = std::sqrt(std::max(0.0f, 1.0f / s2 - 1.0f));
    // y: cos of the azimuth where the cap's rim meets the horizon.
    const float y = std::clamp(-cotSigma * c / sinTheta, -1.0f, 1.0f);
    const float rim = sinTheta * std::sqrt(1.0f - y * y);
    const float piF = (c * std::acos(y) - cotSigma * rim) * s2 + std::atan2(rim, cotSigma);
    return std::clamp(piF / kPi, 0.0f, 1.0f);
}

float sphereCapWithin(float d, float r, float R) {
    if (d <= r * (1.0f + kOnSurface)) return -1.0f;
    if (d - r >= R) return 0.0f;
    const float d2 = d * d, r2 = r * r;
    if (d2 - r2 <= R * R) return r2 / d2;
    const float cosB = std::clamp((d2 + R * R - r2) / (2.0f * d * R), -1.0f, 1.0f);
    return 1.0f - cosB * cosB;
}

float sphereOcclusion(V3f p, V3f n, V3f c, float r, float R) {
    const V3f v = c - p;
    const float d = length(v);
    const float s2 = sphereCapWithin(d, r, R);
    if (!(s2 > 0)) return 0.0f;
    return capOcclusion(dot(n, v) / d, s2);
}

namespace {

// 2 asin(x), the angle across a line of radius r seen from distance d
// (x = r / d): by its Taylor series below x = 0.5 (relative error under
// 2e-4 there, far less below), which covers nearly every piece.
float acrossAngle(float x) {
    if (x >= 0.5f) return 2.0f * std::asin(std::min(1.0f, x));
    const float x2 = x * x;
    return 2.0f * x * (1.0f + x2 * (1.0f / 6.0f + x2 * (3.0f / 40.0f + x2 * (15.0f / 336.0f))));
}

// The integrand at one point x (relative to the receiver) of a line with
// unit tangent t and radius r there; 0 inside the line or beyond R.
float tubeIntegrand(V3f x, V3f n, V3f t, float r, float R) {
    const float d = length(x);
    if (d <= r || d - r >= R) return 0.0f;
    const V3f u = x * (1.0f / d);
    const float facing = dot(n, u);
    if (facing <= 0) return 0.0f;
    const float across = acrossAngle(r / d);
    return across * length(cross(t, u)) * facing / d;
}

}  // namespace

float thinPiece(V3f v, float d, V3f n, V3f t, float r, float len) {
    const float facing = dot(n, v);
    if (facing <= 0 || d <= r) return 0.0f;
    const float inv = 1.0f / d, along = dot(t, v) * inv;
    const float across = acrossAngle(r * inv);
    // |t x u| = sqrt(1 - (t . u)^2); (n . u) / d = facing / d^2.
    const float sinTU = std::sqrt(std::max(0.0f, 1.0f - along * along));
    return std::min(1.0f, across * sinTU * facing * inv * inv * len / kPi);
}

float tubeOcclusion(V3f p, V3f n, V3f a, V3f b, float ra, float rb, float R) {
    const V3f ab = b - a;
    const float len = length(ab);
    if (!(len > 0)) return 0.0f;  // a lone point of a line: its end cap is not modelled
    const V3f t = ab * (1.0f / len);
    const V3f w = a - p;
    // The part of the line inside the ball of radius R + r around p.
    const float reach = R + std::max(ra, rb);
    const float half = dot(w, t), c = dot(w, w) - reach * reach;
    const float disc = half * half - c;
    if (disc <= 0) return 0.0f;
    const float root = std::sqrt(disc);
    const float s0 = std::max(0.0f, -half - root), s1 = std::min(len, -half + root);
    if (!(s1 > s0)) return 0.0f;
    const float closest = length(w + t * std::clamp(-half, s0, s1));
    const int pieces = int(std::clamp(std::ceil((s1 - s0) / std::max(0.5f * closest, 1e-20f)), 1.0f, 16.0f));
    const float h = (s1 - s0) / float(pieces);
    // Two-point Gauss-Legendre: nodes at the piece's middle +- h / (2 sqrt 3).
    const float offset = h * 0.28867513f;
    float sum = 0;
    for (int k = 0; k < pieces; ++k) {
        const float mid = s0 + (float(k) + 0.5f) * h;
        for (const float s : {mid - offset, mid + offset}) {
            const float r = ra + (rb - ra) * (s / len);
            sum += tubeIntegrand(w + t * s, n, t, r, R);
        }
    }
    return std::min(1.0f, sum * 0.5f * h / kPi);
}

}  // namespace darkroom::listao
