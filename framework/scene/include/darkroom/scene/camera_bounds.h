#pragma once
// Bounds on camera values: one home for the rule that scene files
// (scene_file.cpp) and the in situ API (insitu/) both apply. Cameras are ray
// traced in single precision (Embree). Beyond a million scene radii a camera
// sees nothing but rounding, and values far beyond that overflow a float and
// abort inside Embree; a field of view near 0 or 180 degrees does the same
// through tan(). docs/scene-format.md ("Bounds") and docs/insitu.md.
//
// The reach is relative to the scene, so a huge scene may still place a
// camera where a float cannot start a ray: Embree asserts on ray origins
// beyond 1.8e18 (its FLT_LARGE), whatever the scene; rayOriginProblem checks
// the cameras themselves against that.
//
// Each check returns "" when the value is acceptable, else what is wrong
// ("distance 1e+20 is too far: ..."), for the caller to prefix with where the
// value came from (a scene file's line, an API call).
#include <darkroom/camera.h>
#include <darkroom/export.h>
#include <darkroom/scene.h>

#include <string>

namespace darkroom::camera_bounds {

inline constexpr double kReach = 1e6;                        // scene radii
inline constexpr double kMinFov = 1e-3, kMaxFov = 179.999;  // degrees
inline constexpr double kMaxCoordinate = 1e18;               // world units from the origin, below Embree's 1.8e18

// What the bounds below measure with: the half-diagonal of `b` (1 for an
// empty or point-sized scene) and its centre (the origin when empty).
DARKROOM_API double sceneRadius(const Bounds& b);
DARKROOM_API Vec3 sceneCentre(const Bounds& b);

// A perspective camera's vertical field of view, in degrees.
DARKROOM_API std::string fovProblem(double degrees);
// A camera's distance from its orbit's target.
DARKROOM_API std::string distanceProblem(double distance, double radius);
// A camera position or target (`what`): every coordinate, measured from the
// scene's centre, within kReach radii.
DARKROOM_API std::string pointProblem(const std::string& what, const Vec3& p, const Vec3& centre, double radius);
// An orthographic view height (world units): within [radius / kReach, radius * kReach].
DARKROOM_API std::string viewHeightProblem(double height, double radius);

// A camera whose rays would start beyond kMaxCoordinate (its position, plus
// an orthographic view's half extent, in any coordinate).
DARKROOM_API std::string rayOriginProblem(const Camera& camera);

// A number as these messages write it ("%.6g": 1e+20).
DARKROOM_API std::string shortNumber(double v);

}  // namespace darkroom::camera_bounds
