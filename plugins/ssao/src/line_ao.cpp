// LineAO (Eichelbaum, Hlawitschka and Scheuermann, "LineAO - Improved
// Three-Dimensional Line Rendering", IEEE TVCG 2013) and PointAO, its
// variant for point data (the same estimator with other defaults, ssao.cpp).
//
// Multi-scale hemisphere sampling: level l of `levels` samples `samples`
// points in the normal's hemisphere of radius r_l (growing as the paper's
// cumulative radius scalers 0.5, 0.5 + 3/L, ...) and reads depth and normal
// at each point's pixel from level l of a mean pyramid, so coarse levels see
// the density of geometry rather than single pixels. A pixel nearer to the
// camera than the receiver by delta occludes it with weight
//   (1 - smoothstep(eps, zone_l, delta)) * (1 - n_receiver . n_occluder),
// the zone of influence zone_l = zone R (1 - l/L)^2 shrinking with the level
// (distant occluders at coarse scales count less), and the normal difference
// making parallel neighbours (a bundle of lines, a plane) occlude little.
//   AO = 1 - strength / (L S) * sum of the weights.
// This is the papers' perceptual estimator, not cosine-weighted visibility:
// `strength` and `zone` set how dark it gets (README: what that costs against
// ray-traced AO).
#include "ao_estimators.h"
#include "scalar_pixel.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace darkroom::ssao {
namespace {

constexpr float kGoldenAngle = 2.39996322972865332f;
constexpr float kPlastic = 0.754877666246692760f;  // 1 / plastic number: a 1D low-discrepancy step

float smoothstep(float e0, float e1, float x) {
    const float t = std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

// Radius of level l as a fraction of R: the paper's scalers 0.5 + 3 k / L,
// summed up to l, over their sum up to L - 1.
std::vector<float> levelRadii(int levels) {
    std::vector<float> r(static_cast<std::size_t>(levels));
    float sum = 0;
    for (int l = 0; l < levels; ++l) r[std::size_t(l)] = sum += 0.5f + 3.0f * float(l) / float(levels);
    for (float& v : r) v /= sum;
    return r;
}

float lineAoPixel(const Frame& g, const Pyramid& pyr, const AoSettings& s, const std::vector<float>& radii, int x,
                  int y) {
    Receiver r;
    if (!makeReceiver(g, pyr.levels[0], s, x, y, r)) return 1.0f;
    const int L = s.levels, S = s.samples, top = int(pyr.levels.size()) - 1;
    const float W = float(g.width()), H = float(g.height());
    const float eps = std::max(s.bias * r.R, 1e-6f * r.z);
    // Tangent frame, rotated per pixel.
    const V3f helper = std::fabs(r.n.x) < 0.9f ? V3f{1, 0, 0} : V3f{0, 1, 0};
    const V3f t0 = normalize(cross(helper, r.n)), b0 = cross(r.n, t0);
    const float spin = 2.0f * std::numbers::pi_v<float> * r.spin;
    float occlusion = 0;
    for (int l = 0; l < L; ++l) {
        const PyramidLevel& P = pyr.levels[std::size_t(std::min(l, top))];
        const int shift = std::min(l, top);
        const float radius = radii[std::size_t(l)] * r.R;
        const float fade = 1.0f - float(l) / float(L);
        const float zone = std::max(s.zone * r.R * fade * fade, 2.0f * eps);
        for (int k = 0; k < S; ++k) {
            // Cosine-distributed directions (a Vogel spiral lifted to the
            // hemisphere), distances uniform in the ball's volume.
            const float disc = std::sqrt((float(k) + 0.5f) / float(S));
            const float a = spin + float(k + l * S) * kGoldenAngle;
            const V3f dir = r.n * std::sqrt(std::max(0.0f, 1.0f - disc * disc)) + t0 * (disc * std::cos(a)) +
                            b0 * (disc * std::sin(a));
            float u = r.jitter + float(k + l * S) * kPlastic;
            u -= std::floor(u);
            const V3f q = r.p + dir * (radius * std::cbrt(0.02f + 0.98f * u));
            if (g.perspective() && q.z <= 0) continue;
            float tx, ty;
            projectTo(g, q, tx, ty);
            if (!(tx >= 0 && ty >= 0 && tx < W && ty < H)) continue;
            const std::size_t at = P.at(std::min(int(tx) >> shift, P.width - 1), std::min(int(ty) >> shift, P.height - 1));
            const float delta = r.z - P.z[at];  // > 0: the occluder is nearer the camera; background: -inf
            if (!(delta > eps)) continue;
            const float normalDifference = 1.0f - (r.n.x * P.n[0][at] + r.n.y * P.n[1][at] + r.n.z * P.n[2][at]);
            occlusion += (1.0f - smoothstep(eps, zone, delta)) * normalDifference;
        }
    }
    return std::clamp(1.0f - s.strength * occlusion / float(L * S), 0.0f, 1.0f);
}

}  // namespace

void lineAO(const Frame& g, const Pyramid& p, const AoSettings& s, int y, const std::int32_t* xs, int count, float* ao) {
    const std::vector<float> radii = levelRadii(s.levels);
    const std::size_t row = g.offset(0, y);
    if (!xs) {
        for (int x = 0; x < g.width(); ++x) ao[row + std::size_t(x)] = lineAoPixel(g, p, s, radii, x, y);
        return;
    }
    for (int i = 0; i < count; ++i) ao[row + std::size_t(xs[i])] = lineAoPixel(g, p, s, radii, xs[i], y);
}

}  // namespace darkroom::ssao
