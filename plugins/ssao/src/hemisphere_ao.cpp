// Classic normal-oriented hemisphere estimator (Crytek 2007 as reformulated
// around the normal by Bavoil and Sainz, "Screen Space Ambient Occlusion",
// NVIDIA 2008): points inside the hemisphere of radius R above the receiver
// are tested against the depth buffer; a point behind the visible surface is
// occluded, weighted by a range check on the occluder's distance.
#include "ao_estimators.h"
#include "noise.h"

#include <cmath>

namespace darkroom::ssao {

void hemisphereAO(const PixelGeometry& g, const AoSettings& s, Context& ctx, float* ao) {
    constexpr float kTwoPi = 6.28318530717958647692f;
    constexpr float kGoldenAngle = 2.39996322972865332f;  // pi (3 - sqrt 5)
    constexpr float kPlastic = 0.754877666246692760f;     // 1 / plastic number: a 1D low-discrepancy step
    const int n = s.samples;
    ctx.parallelFor(0, g.height(), 4, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < g.width(); ++x) {
                const std::size_t i = g.index(x, y);
                ao[i] = 1.0f;
                if (!g.valid[i]) continue;
                const V3f p = g.points[i];
                const V3f nrm = g.normal[i];
                const float R = s.worldRadius(g, p.z);
                // Tangent frame rotated by a per-pixel angle.
                const V3f helper = std::fabs(nrm.x) < 0.9f ? V3f{1, 0, 0} : V3f{0, 1, 0};
                const V3f t0 = normalize(cross(helper, nrm));
                const V3f b0 = cross(nrm, t0);
                const float rot = kTwoPi * pixelNoise(x, y, s.seed, 0);
                const float jitter = pixelNoise(x, y, s.seed, 1);
                const V3f origin = p + nrm * (s.bias * R);
                const float thick = s.thickness * R;
                float occlusion = 0;
                for (int k = 0; k < n; ++k) {
                    // Cosine-distributed directions (a Vogel spiral on the unit
                    // disc lifted to the hemisphere, Malley's method) ...
                    const float r = std::sqrt((float(k) + 0.5f) / float(n));
                    const float a = rot + float(k) * kGoldenAngle;
                    const float ca = std::cos(a), sa = std::sin(a);
                    const V3f dir = t0 * (r * ca) + b0 * (r * sa) + nrm * std::sqrt(std::max(0.0f, 1.0f - r * r));
                    // ... at distances uniform in the volume of the ball (as
                    // Crytek's points in a sphere). Against a solid occluder
                    // hit at distance t along the ray this counts 1 - (t/R)^3
                    // instead of ray-traced AO's 1: the closest a single-point
                    // test gets (the popular lerp(0.1, 1, u^2) gives
                    // 1 - sqrt((t/R - 0.1) / 0.9), far less occlusion).
                    float u = jitter + float(k) * kPlastic;
                    u -= std::floor(u);
                    const V3f q = origin + dir * (R * std::cbrt(0.02f + 0.98f * u));
                    float px, py;
                    if (!g.project(q, px, py)) continue;
                    if (!(px >= 0 && py >= 0 && px < float(g.width()) && py < float(g.height()))) continue;
                    const std::size_t j = g.index(int(px), int(py));
                    if (!g.valid[j]) continue;  // background never occludes
                    const V3f occ = g.points[j];
                    if (!(q.z > occ.z)) continue;  // the sample point is in front of the surface
                    if (s.geometry == Geometry::Points &&
                        (!pointsOccluderAllowed(occ.z, p.z, thick) || q.z > occ.z + thick))
                        continue;
                    occlusion += falloffWeight(std::fabs(p.z - occ.z), R, s.falloff);
                }
                ao[i] = std::clamp(1.0f - occlusion / float(n), 0.0f, 1.0f);
            }
    });
}

}  // namespace darkroom::ssao
