#pragma once
// The two occlusion estimators. Both write raw AO in [0, 1] (1 = unoccluded)
// for every pixel into a plane of the frame's layout; pixels without valid
// depth get 1.
#include "frame.h"

#include <darkroom/context.h>

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
    bool interleave = false;          // stratify the rotation noise over 2 x 2 blocks of even pixels (half resolution)
    int levels = 3;                   // lineao, pointao: hemisphere radii, one pyramid level each
    float zone = 0.5f;                // lineao, pointao: zone of influence of level 0, in radii
    float strength = 1.0f;            // lineao, pointao: occlusion scale
};

struct Pyramid;

// Both estimators weight an occluder at distance `dist` from the receiver by
// 1 inside (1 - falloff) * radius, fading linearly to 0 at the radius; a hard
// cut when falloff is 0 (the definition of ray-traced AO with a maximum
// distance).
//
// Points geometry: the visible surface at depth Zo may occlude a receiver at
// depth Zr only when it is nearer and within the assumed thickness
// (Zo < Zr <= Zo + thickness * R): a particle far in front is a separate
// object whose back side does not reach the receiver.

// Rows [y0, y1) of AO, written at frame.offset(x, y) of `ao`.
void hemisphereAO(const Frame& g, const AoSettings& s, int y0, int y1, float* ao);
void horizonAO(const Frame& g, const AoSettings& s, int y0, int y1, float* ao);
// AO of the pixels (xs[i], y), i < count, only; each pixel gets exactly the
// value the row functions give it.
void hemisphereAOAt(const Frame& g, const AoSettings& s, int y, const std::int32_t* xs, int count, float* ao);
void horizonAOAt(const Frame& g, const AoSettings& s, int y, const std::int32_t* xs, int count, float* ao);

// The pyramid estimators (scalar, per pixel): row y, every pixel when xs is
// null, else the count pixels xs. LineAO and PointAO read a Reduction::Mean
// pyramid with at least s.levels levels, SAO a Reduction::RotatedGrid one.
void lineAO(const Frame& g, const Pyramid& p, const AoSettings& s, int y, const std::int32_t* xs, int count, float* ao);
void saoAO(const Frame& g, const Pyramid& p, const AoSettings& s, int y, const std::int32_t* xs, int count, float* ao);

}  // namespace darkroom::ssao
