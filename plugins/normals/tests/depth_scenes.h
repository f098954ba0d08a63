#pragma once
// Analytic depth images for the tests of the depth-based passes (Normals, IBS,
// SSDD): planes and steps seen by a perspective or orthographic camera, with
// depth computed by intersecting Camera::ray with the plane in double.
#include "test_support.h"

#include <darkroom/buffer.h>
#include <darkroom/camera.h>
#include <darkroom/core/run_filter.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <numbers>
#include <string>
#include <vector>

namespace darkroom::test {

inline Camera viewCamera(int w, int h, bool perspective) {
    Camera c;
    c.width = w;
    c.height = h;
    c.position = {0.3, -0.2, 5.0};
    c.forward = normalize(Vec3{-0.05, 0.04, -1.0});  // slightly oblique, so no axis is special
    c.up = {0, 1, 0};
    c.projection = perspective ? Camera::Projection::Perspective : Camera::Projection::Orthographic;
    c.fovYDegrees = 40;
    c.viewHeight = 3.0;
    return c;
}

struct ScenePlane {
    Vec3 point;
    Vec3 normal;  // unit
};

// Planar depth at the centre of pixel (x, y) of the plane; +inf when missed.
inline double planeDepth(const Camera& c, const ScenePlane& p, int x, int y) {
    Vec3 o, d;
    c.ray(x + 0.5, y + 0.5, o, d);
    const double t = dot(p.point - o, p.normal) / dot(d, p.normal);
    // Perspective rays have unit forward component and orthographic rays are
    // unit and forward, so t is the planar depth in both cases.
    return t > 0 ? t : std::numeric_limits<double>::infinity();
}

// An image with Z = depth(x, y), the camera in its metadata and the extra
// float channels filled with `fill`.
inline std::shared_ptr<WritableBuffer> depthImage(const Camera& c,
                                                  const std::function<double(int, int)>& depth,
                                                  const std::vector<std::string>& extra = {},
                                                  float fill = 0.5f) {
    std::vector<std::string> names{"Z"};
    names.insert(names.end(), extra.begin(), extra.end());
    auto b = makeImage(c.width, c.height, names, [&](int x, int y, int ch) {
        return ch == 0 ? float(depth(x, y)) : fill;
    });
    b->metadata().camera = c;
    return b;
}

// The facing-the-camera orientation of a plane normal.
inline Vec3 facing(const Camera& c, const ScenePlane& p) {
    return dot(p.normal, c.forward) < 0 ? p.normal : -p.normal;
}

inline double angleDegrees(const Vec3& a, const Vec3& b) {
    const double c = dot(normalize(a), normalize(b));
    return std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / std::numbers::pi;
}

using Inputs = std::map<std::string, std::vector<Value>>;

inline BufferPtr runPass(const std::string& type, const BufferPtr& image, Inputs extra = {},
                         int threads = 2) {
    auto f = pluginRegistry().createFilter(type);
    extra["image"] = {Value(image)};
    FilterRunOptions o;
    o.threads = threads;
    return runFilter(*f, extra, o).outputs.at("image").asImage();
}

inline Vec3 vec(const Buffer& b, const std::string& prefix, std::size_t i) {
    return {b.hostFloat(prefix + ".x")[i], b.hostFloat(prefix + ".y")[i], b.hostFloat(prefix + ".z")[i]};
}

}  // namespace darkroom::test
