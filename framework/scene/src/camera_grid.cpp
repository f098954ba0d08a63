// Camera placement for scene files: the Cinema phi/theta orbit and the
// distance at which the scene's bounding sphere fills the view.
#include <darkroom/scene/scene_file.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace darkroom {
namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
}

std::vector<double> phiAngles(int count) {
    std::vector<double> a;
    for (int i = 0; i < count; ++i) a.push_back(-180.0 + 360.0 * i / count);
    return a;
}

std::vector<double> thetaAngles(int count) {
    if (count == 1) return {0.0};
    std::vector<double> a;
    for (int i = 0; i < count; ++i) a.push_back(-90.0 + 180.0 * i / (count - 1));
    return a;
}

Camera orbitCamera(const Camera& prototype, const Vec3& target, double distance, double phiDegrees,
                   double thetaDegrees, const Vec3& up) {
    const Vec3 u = normalize(up);
    Vec3 f = cross(Vec3{1, 0, 0}, u);
    if (length(f) < 1e-9) f = cross(u, Vec3{0, 1, 0});  // up along X
    f = normalize(f);
    const Vec3 r = cross(u, f);
    const double phi = phiDegrees * kDeg, theta = thetaDegrees * kDeg;
    const Vec3 horizontal = f * std::cos(phi) + r * std::sin(phi);
    const Vec3 dir = horizontal * std::cos(theta) + u * std::sin(theta);
    Camera c = prototype;
    c.position = target + dir * distance;
    c.forward = -dir;
    // d(dir)/d(theta): orthogonal to the view direction, equal to U at theta = 0.
    c.up = u * std::cos(theta) - horizontal * std::sin(theta);
    return c;
}

double fittingDistance(const Camera& prototype, double radius) {
    if (prototype.projection == Camera::Projection::Orthographic) return 2.0 * radius;
    const double aspect = prototype.height > 0 ? double(prototype.width) / prototype.height : 1.0;
    const double halfY = prototype.fovYDegrees * kDeg * 0.5;
    const double halfX = std::atan(std::tan(halfY) * aspect);
    return radius / std::sin(std::min(halfX, halfY));
}

}  // namespace darkroom
