#pragma once
// The two occlusion estimators. Both write raw AO in [0, 1] (1 = unoccluded)
// for every pixel; pixels without valid depth get 1.
#include "pixel_geometry.h"

#include <darkroom/context.h>

#include <algorithm>
#include <cstdint>

namespace darkroom::ssao {

enum class Geometry { Surface, Points };

struct AoSettings {
    float radius = 1;                 // world units, or a fraction of the image height
    bool radiusInImageHeight = false;
    int samples = 16;                 // hemisphere
    int slices = 4, steps = 8;        // horizon
    float falloff = 0.2f;             // fraction of the radius over which occluder weight fades to 0
    float bias = 0.01f;               // receiver lifted along its normal by bias * radius
    float thickness = 0.5f;           // points geometry: occluder thickness along the view, in radii
    std::uint32_t seed = 0;
    Geometry geometry = Geometry::Surface;

    // Occlusion radius in world units at planar depth z.
    float worldRadius(const PixelGeometry& g, float z) const {
        return radiusInImageHeight ? radius * float(g.height()) * g.pixelSizeAt(z) : radius;
    }
};

// Weight of an occluder at distance `dist` from the receiver: 1 inside
// (1 - falloff) * radius, fading linearly to 0 at the radius; a hard cut when
// falloff is 0 (the definition of ray-traced AO with a maximum distance).
inline float falloffWeight(float dist, float radius, float falloff) {
    if (falloff <= 0) return dist <= radius ? 1.0f : 0.0f;
    return std::clamp((radius - dist) / (falloff * radius), 0.0f, 1.0f);
}

// Points geometry: may the visible surface at depth `occluderZ` occlude a
// receiver at depth `receiverZ`? Only nearer surfaces do, and only within the
// assumed thickness: a particle far in front is a separate object whose back
// side does not reach the receiver.
inline bool pointsOccluderAllowed(float occluderZ, float receiverZ, float thickness) {
    return occluderZ < receiverZ && receiverZ - occluderZ <= thickness;
}

void hemisphereAO(const PixelGeometry& g, const AoSettings& s, Context& ctx, float* ao);
void horizonAO(const PixelGeometry& g, const AoSettings& s, Context& ctx, float* ao);

}  // namespace darkroom::ssao
