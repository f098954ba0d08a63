#include "list_occlusion.h"

#include "closed_forms.h"

#include <algorithm>
#include <cmath>

namespace darkroom::listao {

float ListOcclusion::visibility(V3f p, V3f n, float R) const {
    const Primitives& s = grid_.primitives();
    float visible = 1.0f;
    grid_.visit(
        p, R,
        [&](std::uint32_t b, std::uint32_t e) {
            for (std::uint32_t i = b; i < e; ++i) {
                const V3f v = s.centres[i] - p;
                const float r = s.radii[i], d2 = dot(v, v), reach = R + r;
                if (d2 >= reach * reach) continue;
                // n . v against r decides the horizon without a square root:
                // wholly below (skipped) or wholly above, where a sphere whose
                // rim is within R covers (r / d)^2 cos(theta) = r^2 (n . v) / d^3.
                const float nv = dot(n, v);
                if (nv <= -r) continue;
                if (nv >= r && d2 - r * r <= R * R && d2 > r * r) {
                    visible *= 1.0f - r * r * nv / (d2 * std::sqrt(d2));
                    continue;
                }
                visible *= 1.0f - sphereOcclusion(p, n, s.centres[i], r, R);
            }
        },
        [&](std::uint32_t b, std::uint32_t e) {
            for (std::uint32_t i = b; i < e; ++i) {
                // Reject by the segment's bounding sphere; a segment far for
                // its length and wholly within R is one midpoint sample
                // (thinPiece), the rest the full rule.
                const V3f v = s.segMid[i] - p;
                const float d2 = dot(v, v), reach = R + s.segReach[i];
                if (d2 >= reach * reach) continue;
                const float len = s.segLen[i];
                if (d2 > 16.0f * len * len && d2 < (R - s.segReach[i]) * (R - s.segReach[i]) && R > s.segReach[i])
                    visible *= 1.0f - thinPiece(v, std::sqrt(d2), n, s.segDir[i], 0.5f * (s.segRa[i] + s.segRb[i]), len);
                else
                    visible *= 1.0f - tubeOcclusion(p, n, s.segA[i], s.segB[i], s.segRa[i], s.segRb[i], R);
            }
        });
    return std::clamp(visible, 0.0f, 1.0f);
}

bool ListOcclusion::surfaceNormal(V3f p, float tolerance, V3f& n) const {
    const Primitives& s = grid_.primitives();
    float best = tolerance;
    bool found = false;
    auto consider = [&](V3f from, float r) {
        const V3f v = p - from;
        const float d = length(v);
        if (std::fabs(d - r) <= best && d > 0) {
            best = std::fabs(d - r);
            n = v * (1.0f / d);
            found = true;
        }
    };
    grid_.visit(
        p, tolerance,
        [&](std::uint32_t b, std::uint32_t e) {
            for (std::uint32_t i = b; i < e; ++i) consider(s.centres[i], s.radii[i]);
        },
        [&](std::uint32_t b, std::uint32_t e) {
            for (std::uint32_t i = b; i < e; ++i) {
                // The nearest point of the segment's axis, and its radius there.
                const V3f ab = s.segB[i] - s.segA[i];
                const float len2 = dot(ab, ab);
                const float t = len2 > 0 ? std::clamp(dot(p - s.segA[i], ab) / len2, 0.0f, 1.0f) : 0.0f;
                consider(s.segA[i] + ab * t, s.segRa[i] + (s.segRb[i] - s.segRa[i]) * t);
            }
        });
    return found;
}

}  // namespace darkroom::listao
