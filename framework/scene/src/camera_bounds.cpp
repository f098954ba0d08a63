#include <darkroom/scene/camera_bounds.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace darkroom::camera_bounds {

double sceneRadius(const Bounds& b) { return b.empty() || b.radius() <= 0 ? 1.0 : b.radius(); }

Vec3 sceneCentre(const Bounds& b) { return b.empty() ? Vec3{} : b.center(); }

std::string shortNumber(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

std::string fovProblem(double degrees) {
    if (degrees >= kMinFov && degrees <= kMaxFov) return {};
    return "fov must lie in [" + shortNumber(kMinFov) + ", " + shortNumber(kMaxFov) + "] degrees, got " +
           shortNumber(degrees);
}

std::string distanceProblem(double distance, double radius) {
    if (!(distance > 0)) return "distance must be positive";
    if (distance > kReach * radius)
        return "distance " + shortNumber(distance) + " is too far: cameras must lie within " + shortNumber(kReach) +
               " scene radii (radius " + shortNumber(radius) + ") of the scene";
    return {};
}

std::string pointProblem(const std::string& what, const Vec3& p, const Vec3& centre, double radius) {
    const Vec3 d = p - centre;
    const double far = std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)});
    if (far <= kReach * radius) return {};  // false for NaN too
    return what + " [" + shortNumber(p.x) + ", " + shortNumber(p.y) + ", " + shortNumber(p.z) +
           "] is too far from the scene: cameras must lie within " + shortNumber(kReach) + " scene radii (radius " +
           shortNumber(radius) + ") of its centre";
}

std::string viewHeightProblem(double height, double radius) {
    if (!(height > 0)) return "height must be positive (world units)";
    if (height > kReach * radius || height < radius / kReach)
        return "height " + shortNumber(height) + " is out of proportion to the scene: it must lie between " +
               shortNumber(1 / kReach) + " and " + shortNumber(kReach) + " times the scene's radius (" +
               shortNumber(radius) + ")";
    return {};
}

std::string rayOriginProblem(const Camera& c) {
    // An orthographic view's rays start across it: half its height and width.
    const double extent = c.projection == Camera::Projection::Orthographic
                              ? c.halfHeight() * (1.0 + double(c.width) / std::max(1, c.height))
                              : 0.0;
    const Vec3& p = c.position;
    const double far = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}) + extent;
    if (far <= kMaxCoordinate) return {};  // false for NaN too
    return "position [" + shortNumber(p.x) + ", " + shortNumber(p.y) + ", " + shortNumber(p.z) + "]" +
           (extent > 0 ? " with the view's half extent (" + shortNumber(extent) + ")" : std::string()) +
           " reaches beyond " + shortNumber(kMaxCoordinate) + " world units from the origin, where the ray tracer's single precision cannot start "
           "rays; bring the camera nearer the scene, or the scene nearer the origin";
}

}  // namespace darkroom::camera_bounds
