#pragma once
// The per-pixel decision of FXAA 3.11 quality, on a precomputed luma plane.
// FXAA's output is always the centre colour moved towards ONE of its four
// edge neighbours (its final bilinear fetch is offset along a single axis by
// at most one pixel), so the decision is that neighbour and a weight.
#include "fxaa_presets.h"

namespace darkroom::fxaa {

struct Settings {
    const Preset* preset = nullptr;
    float subpix = 0.75f;             // amount of sub-pixel aliasing removal, 0..1
    float edgeThreshold = 0.166f;     // local contrast needed, relative to the local maximum luma
    float edgeThresholdMin = 0.0833f; // ... and in absolute luma (skips dark areas)
};

// Row-major luma, NaN where the pixel must not be blended (see luma.h).
struct LumaPlane {
    const float* luma;
    int width;
    int height;
};

struct Blend {
    int dx = 0, dy = 0;    // the neighbour blended in: one of (+-1, 0), (0, +-1); (0,0) = none
    float amount = 0.0f;   // result = (1 - amount) centre + amount neighbour, amount in [0, 1]
};

// The decision for pixel (x, y), whose luma must not be NaN. Samples outside
// the image are clamped to the border (as a texture fetch would be); NaN
// samples count as equal to the centre, so invalid data brings no contrast
// and no edge. The caller still must not blend an invalid neighbour in.
Blend decide(const LumaPlane& plane, int x, int y, const Settings& s);

}  // namespace darkroom::fxaa
