#pragma once
#include <darkroom/depth_input.h>
#include <darkroom/filter.h>

#include "ao_estimators.h"
#include "frame_cache.h"

namespace darkroom {

// SSAO: screen-space ambient occlusion from depth and the camera. Adds channel
// `AO` in [0, 1] (1 = unoccluded) and passes every input channel through.
class Ssao final : public Filter {
public:
    enum class Method { Hemisphere, Horizon, LineAO, PointAO, Sao };
    enum class GeometryKind { Surface, Points };
    enum class RadiusUnits { World, ImageHeight };
    enum class Resolution { Full, Half };

    PortList ports() const override;
    void execute(Context& ctx) override;
    void beginSequence(const SequenceInfo& info) override;

private:
    ssao::AoSettings settings(Context& ctx) const;  // the estimator's parameters from the ports

    ImageIn image_{"image", "G-buffer with planar depth Z (+inf = background) and, best, a camera in its metadata (without one it is shaded in image space)", {"Z"}};
    EnumIn<Method> method_{"method",
                           {{Method::Hemisphere, "hemisphere"},
                            {Method::Horizon, "horizon"},
                            {Method::LineAO, "lineao"},
                            {Method::PointAO, "pointao"},
                            {Method::Sao, "sao"}},
                           Method::Horizon,
                           "hemisphere: classic normal-oriented point sampling with a range check; horizon: "
                           "GTAO-style slices with an analytic cosine-weighted inner integral (comparable to "
                           "ray-traced AO of the same radius); lineao: multi-scale hemispheres over a depth/normal "
                           "pyramid weighted by depth zone and normal difference (LineAO, Eichelbaum et al. 2012); "
                           "pointao: the same estimator with defaults for particles (PointAO, Eichelbaum et al. "
                           "2013); sao: Scalable Ambient Obscurance (McGuire et al. 2012), spiral taps over a depth "
                           "MIP chain, cost independent of the radius"};
    EnumIn<GeometryKind> geometry_{"geometry",
                                   {{GeometryKind::Surface, "surface"}, {GeometryKind::Points, "points"}},
                                   GeometryKind::Surface,
                                   "surface: the depth buffer is a height field (solid behind every pixel); points: "
                                   "particles and thin lines, only nearer occluders within `thickness` count"};
    FloatIn radius_{"radius", 0.05, 1e-6, 1e9, "Occlusion radius, in radiusUnits"};
    EnumIn<RadiusUnits> radiusUnits_{"radiusUnits",
                                     {{RadiusUnits::World, "world"}, {RadiusUnits::ImageHeight, "imageHeight"}},
                                     RadiusUnits::ImageHeight,
                                     "world: world units; imageHeight: a fraction of the image height, converted to "
                                     "world units at each pixel's depth"};
    IntIn samples_{"samples", 16, 1, 1024,
                   "hemisphere: sample points per pixel; lineao, pointao: points per pyramid level; sao: spiral taps "
                   "per pixel"};
    IntIn levels_{"levels", 0, 0, 8,
                  "lineao, pointao: hemisphere radii, one pyramid level each; 0 = the method's default (lineao 3, "
                  "pointao 3)"};
    FloatIn zone_{"zone", 0.0, 0.0, 100.0,
                  "lineao, pointao: zone of influence of the finest level, in radii (occluders nearer the camera by "
                  "more count less); 0 = the method's default (lineao 0.5, pointao 1)"};
    FloatIn strength_{"strength", 0.0, 0.0, 100.0,
                      "lineao, pointao: occlusion scale of the estimator; 0 = the method's default (lineao 5, pointao 5)"};
    IntIn slices_{"slices", 4, 1, 64, "horizon: slice planes per pixel"};
    IntIn steps_{"steps", 8, 1, 256, "horizon: depth samples per side of each slice"};
    FloatIn falloff_{"falloff", 0.2, 0.0, 1.0,
                     "Fraction of the radius over which an occluder's weight fades to 0 at the radius; 0 = "
                     "hard cut as in ray-traced AO"};
    FloatIn bias_{"bias", 0.01, 0.0, 0.5,
                  "The receiver is lifted along its normal by bias x radius, against self-occlusion "
                  "from depth quantisation and curvature"};
    FloatIn thickness_{"thickness", 0.5, 0.0, 1e6,
                       "points geometry: assumed occluder thickness along the view, in units of the radius"};
    FloatIn intensity_{"intensity", 1.0, 0.0, 10.0, "Scales occlusion: AO = 1 - intensity (1 - AO), then clamped"};
    FloatIn power_{"power", 1.0, 0.1, 10.0, "Exponent applied to AO after intensity"};
    IntIn seed_{"seed", 0, 0, 2147483647, "Seed of the per-pixel noise (hash of pixel and seed)"};
    IntIn blurRadius_{"blurRadius", 2, 0, 32, "Half-width in pixels of the depth-aware blur; 0 disables it"};
    EnumIn<Resolution> resolution_{"resolution",
                                   {{Resolution::Full, "full"}, {Resolution::Half, "half"}},
                                   Resolution::Half,
                                   "half: the estimator at the pixels with even x and y (on the full-resolution depth, "
                                   "noise interleaved over 2x2 blocks of them), every other pixel the mean of its "
                                   "computed neighbours when all lie on its surface, else computed itself (as accurate "
                                   "as full on the accuracy sweep, about 2.5x faster); full: the estimator at every "
                                   "pixel"};
    BoolIn useNormals_{"useNormals", false,
                       "Use the input's world-space normals N.x/N.y/N.z when present instead of "
                       "reconstructing them from Z"};
    CameraSource camera_;  // the image's camera, or the image-space one (depth_input.h)
    ssao::FrameCache frames_;  // the last execution's depth planes and normals
    ImageOut result_{"image", "The input channels plus AO in [0, 1] (1 = unoccluded; 1 on background)", {"AO"}};
};

}  // namespace darkroom
