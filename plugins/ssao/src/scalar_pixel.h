#pragma once
// Per-pixel scalar helpers of the pyramid estimators (LineAO, PointAO, SAO):
// the receiver's view-space geometry and its noise, computed the same way for
// a pixel whether its row is estimated whole or pixel by pixel (half
// resolution), so both paths give identical values.
#include "ao_estimators.h"
#include "depth_pyramid.h"
#include "noise.h"

#include <darkroom/view_geometry.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace darkroom::ssao {

struct Receiver {
    float z = 0;        // planar depth
    V3f p, n;           // view-space position and unit normal facing the camera
    float pixelSize = 0;  // world size of a pixel at depth z
    float R = 0;          // occlusion radius in world units
    float spin = 0, jitter = 0;  // per-pixel noise in [0, 1)
};

inline float pixelSizeAt(const Frame& g, float z) { return g.perspective() ? g.pixelScale * z : g.pixelScale; }

// View-space position of continuous pixel coordinates (px, py) at depth z.
inline V3f positionAt(const Frame& g, float px, float py, float z) {
    const float sx = g.ax * px + g.bx, sy = g.ay * py + g.by;
    return g.perspective() ? V3f{sx * z, sy * z, z} : V3f{sx, sy, z};
}

// Continuous pixel coordinates of view-space point q (q.z > 0 in perspective).
inline void projectTo(const Frame& g, V3f q, float& px, float& py) {
    const float sx = g.perspective() ? q.x / q.z : q.x, sy = g.perspective() ? q.y / q.z : q.y;
    px = (sx - g.bx) / g.ax;
    py = (sy - g.by) / g.ay;
}

// The half-resolution interleave of simd-inl.h's Stratify, for one pixel.
inline float stratified(int x, int y, float u) {
    const float bx = float((x >> 1) & 1);
    const float k = ((y >> 1) & 1) != 0 ? 3.0f - 2.0f * bx : 2.0f * bx;
    return (k + u) * 0.25f;
}

// False for a pixel without surface (its AO is 1).
inline bool makeReceiver(const Frame& g, const PyramidLevel& base, const AoSettings& s, int x, int y, Receiver& r) {
    const std::size_t i = base.at(x, y);
    r.z = base.z[i];
    if (!(r.z < std::numeric_limits<float>::infinity())) return false;
    r.n = {base.n[0][i], base.n[1][i], base.n[2][i]};
    r.p = positionAt(g, float(x) + 0.5f, float(y) + 0.5f, r.z);
    r.pixelSize = pixelSizeAt(g, r.z);
    r.R = s.radiusInImageHeight ? s.radius * float(g.height()) * r.pixelSize : s.radius;
    r.spin = pixelNoise(x, y, s.seed, 0);
    if (s.interleave) r.spin = stratified(x, y, r.spin);
    r.jitter = pixelNoise(x, y, s.seed, 1);
    return true;
}

// Weight of an occluder at distance `dist`: 1 inside (1 - falloff) R, fading
// linearly to 0 at R (ao_estimators.h).
inline float distanceWeight(float dist, float R, float falloff) {
    if (falloff <= 0) return dist <= R ? 1.0f : 0.0f;
    return std::clamp((R - dist) / (falloff * R), 0.0f, 1.0f);
}

}  // namespace darkroom::ssao
