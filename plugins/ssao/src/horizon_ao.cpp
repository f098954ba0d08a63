// Horizon-based cosine-weighted AO after Jimenez et al. 2016, "Practical
// Realtime Strategies for Accurate Indirect Occlusion" (GTAO). The hemisphere
// is cut into `slices` planes containing the view vector V; in each, the two
// horizon angles h1 <= 0 <= h2 (from V) are found by marching `steps` depth
// samples per side in screen space, and the cosine-weighted visible fraction
// between them is integrated analytically:
//   AO = 1/slices * sum  |n_p| * (a(h1) + a(h2)),
//   a(h) = 1/4 (-cos(2h - g) + cos g + 2 h sin g),
// where n_p is the normal projected into the slice and g its signed angle
// from V. Weighting by |n_p| makes the slice average the exact cosine-weighted
// integral (1 for an unoccluded surface of any orientation).
#include "ao_estimators.h"
#include "noise.h"

#include <cmath>

namespace darkroom::ssao {

namespace {

constexpr float kPi = 3.14159265358979323846f;
constexpr float kHalfPi = 1.57079632679489661923f;

float innerIntegral(float h, float g) {
    return 0.25f * (-std::cos(2.0f * h - g) + std::cos(g) + 2.0f * h * std::sin(g));
}

}  // namespace

void horizonAO(const PixelGeometry& g, const AoSettings& s, Context& ctx, float* ao) {
    const bool points = s.geometry == Geometry::Points;
    ctx.parallelFor(0, g.height(), 4, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < g.width(); ++x) {
                const std::size_t i = g.index(x, y);
                ao[i] = 1.0f;
                if (!g.valid[i]) continue;
                const V3f p = g.points[i];
                const V3f nrm = g.normal[i];
                const V3f v = g.toCamera(p);
                const float R = s.worldRadius(g, p.z);
                const float radiusPixels = R / g.pixelSizeAt(p.z);
                if (!(radiusPixels >= 1.0f)) continue;  // nothing resolvable within a pixel
                const V3f origin = p + nrm * (s.bias * R);
                const float thick = s.thickness * R;
                const float sliceNoise = pixelNoise(x, y, s.seed, 0);
                const float stepNoise = pixelNoise(x, y, s.seed, 1);
                const float cx = float(x) + 0.5f, cy = float(y) + 0.5f;
                // Basis of the plane perpendicular to V.
                const V3f e1 = normalize(V3f{1, 0, 0} - v * v.x);
                const V3f e2 = cross(v, e1);
                float visibility = 0;
                for (int k = 0; k < s.slices; ++k) {
                    const float phi = (float(k) + sliceNoise) * kPi / float(s.slices);
                    // Slices are spread uniformly in angle around V (the
                    // integral's measure), not around the screen axis: for
                    // off-centre pixels of a perspective camera the two
                    // differ, and uniform screen angles bias AO by a few %.
                    const V3f orthoDir = e1 * std::cos(phi) + e2 * std::sin(phi);
                    // The slice plane holds the camera ray, so it projects to a
                    // screen line through the pixel, along d(X/Z, Y/Z).
                    float c = orthoDir.x, sn = orthoDir.y;
                    if (g.perspective()) {
                        c -= orthoDir.z * p.x / p.z;
                        sn -= orthoDir.z * p.y / p.z;
                    }
                    const float screenLen = std::sqrt(c * c + sn * sn);
                    if (!(screenLen > 1e-6f)) continue;
                    c /= screenLen;
                    sn /= screenLen;
                    const V3f axis = normalize(cross(orthoDir, v));
                    const V3f projN = nrm - axis * dot(nrm, axis);
                    const float projLen = length(projN);
                    if (!(projLen > 1e-6f)) continue;
                    const float cosG = std::clamp(dot(projN, v) / projLen, -1.0f, 1.0f);
                    const float gamma = (dot(projN, orthoDir) >= 0 ? 1.0f : -1.0f) * std::acos(cosG);
                    float horizon[2];
                    for (int side = 0; side < 2; ++side) {
                        const float sign = side == 0 ? 1.0f : -1.0f;
                        // Lowest horizon: the edge of the normal's hemisphere.
                        const float lowCos = std::cos(gamma + sign * kHalfPi);
                        float best = lowCos;
                        for (int j = 0; j < s.steps; ++j) {
                            const float dist = std::max(1.0f, (float(j) + stepNoise) / float(s.steps) * radiusPixels);
                            const float sx = cx + sign * c * dist, sy = cy - sign * sn * dist;
                            if (!(sx >= 0 && sy >= 0 && sx < float(g.width()) && sy < float(g.height()))) break;
                            V3f sp;
                            if (!g.surfaceAt(sx, sy, sp)) continue;  // background never occludes
                            if (points && !pointsOccluderAllowed(sp.z, p.z, thick)) continue;
                            // Measured within the slice (a no-op for interpolated
                            // samples, which lie on it; nearest-pixel ones may not).
                            V3f d = sp - origin;
                            d = d - axis * dot(d, axis);
                            const float len = length(d);
                            if (!(len > 0)) continue;
                            const float w = falloffWeight(len, R, s.falloff);
                            const float cosH = dot(d, v) / len;
                            best = std::max(best, lowCos + (cosH - lowCos) * w);
                        }
                        horizon[side] = std::acos(std::clamp(best, -1.0f, 1.0f));
                    }
                    const float h2 = gamma + std::min(horizon[0] - gamma, kHalfPi);
                    const float h1 = gamma + std::max(-horizon[1] - gamma, -kHalfPi);
                    visibility += projLen * (innerIntegral(h1, gamma) + innerIntegral(h2, gamma));
                }
                ao[i] = std::clamp(visibility / float(s.slices), 0.0f, 1.0f);
            }
    });
}

}  // namespace darkroom::ssao
