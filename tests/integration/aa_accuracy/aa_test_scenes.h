#pragma once
// Shared by the anti-aliasing and depth-of-field accuracy tests: small scenes
// made in code whose images are known in closed form (a fronto-parallel
// half-plane with a straight edge), the embree backend, and the pass path
// (ColorMapping then Background) that the references must reproduce.
#include "test_support.h"

#include <darkroom/capture_backend.h>
#include <darkroom/colormap.h>
#include <darkroom/context.h>
#include <darkroom/accuracy/reference.h>
#include <darkroom/core/registry.h>
#include <darkroom/core/run_filter.h>
#include <darkroom/scene.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace darkroom::aatest {

using Inputs = std::map<std::string, std::vector<Value>>;

// The harness's background (bench/accuracy/harness.h), so these tests check
// the same composition the sweeps measure.
inline constexpr Color kBackground{0.25f, 0.25f, 0.25f, 1.0f};
inline constexpr int kThreads = 2;

inline FilterRunOptions runOptions() {
    FilterRunOptions o;
    o.threads = kThreads;
    o.registry = &test::pluginRegistry();
    return o;
}

inline std::unique_ptr<Context> context() { return makeStandaloneContext(runOptions(), "aa-accuracy"); }

inline std::unique_ptr<CaptureBackend> embree(std::shared_ptr<const Scene> scene) {
    auto b = test::pluginRegistry().createBackend("embree");
    if (!b) return nullptr;
    b->setScene(std::move(scene));
    return b;
}

inline BufferPtr runPass(const std::string& type, const BufferPtr& image, Inputs params = {}) {
    auto f = test::pluginRegistry().createFilter(type);
    EXPECT_TRUE(f) << type << " is not built";
    if (!f) return nullptr;
    params["image"] = {Value(image)};
    return runFilter(*f, params, runOptions()).outputs.at("image").asImage();
}

// The pass path: viridis over [lo, hi] on `field`, composited over kBackground.
inline BufferPtr colorize(const BufferPtr& gbuffer, const std::string& field, double lo, double hi) {
    const BufferPtr mapped = runPass("ColorMapping", gbuffer,
                                     {{"channel", {Value(field)}},
                                      {"colormap", {Value(std::string("viridis"))}},
                                      {"range", {Value(std::string("manual"))}},
                                      {"minimum", {Value(lo)}},
                                      {"maximum", {Value(hi)}}});
    return runPass("Background", mapped,
                   {{"mode", {Value(std::string("color"))}}, {"color", {Value(kBackground)}}});
}

// The reference path: the same map and background, per ray sample.
inline reference::SampleShader shader(const std::string& field, double lo, double hi) {
    return reference::colorMapShader(field, loadColorMap("viridis"), lo, hi, kBackground);
}

inline CaptureRequest request(const std::string& field) {
    CaptureRequest r;
    r.scalars = {field};
    return r;
}

// A camera at the origin looking down -z (so planar depth = -z of a point).
inline Camera frontCamera(int size, double fovY = 40.0) {
    Camera c;
    c.position = {0, 0, 0};
    c.forward = {0, 0, -1};
    c.up = {0, 1, 0};
    c.fovYDegrees = fovY;
    c.width = c.height = size;
    return c;
}

// The part of the plane z = -depth on the side a x + b y <= c (clipped to a
// square of half-size `extent`), as two triangles carrying the constant field
// "value" = `value`.
struct HalfPlane {
    double a = 1, b = 0, c = 0;  // world-space edge line
    double depth = 4.0;
    double extent = 50.0;
    float value = 0.7f;
    float gradient = 0.0f;  // d value / d x (world), so a pass can see texture

    bool inside(double x, double y) const { return a * x + b * y <= c; }
};

inline std::shared_ptr<Scene> halfPlaneScene(const std::vector<HalfPlane>& planes) {
    auto scene = std::make_shared<Scene>();
    for (const HalfPlane& h : planes) {
        // Clip the square to the half-plane (one Sutherland-Hodgman step).
        const double e = h.extent;
        const std::vector<std::array<double, 2>> square = {{-e, -e}, {e, -e}, {e, e}, {-e, e}};
        std::vector<std::array<double, 2>> poly;
        for (std::size_t i = 0; i < square.size(); ++i) {
            const auto& p = square[i];
            const auto& q = square[(i + 1) % square.size()];
            const double fp = h.a * p[0] + h.b * p[1] - h.c, fq = h.a * q[0] + h.b * q[1] - h.c;
            if (fp <= 0) poly.push_back(p);
            if ((fp < 0) != (fq < 0) && fp != fq) {
                const double t = fp / (fp - fq);
                poly.push_back({p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])});
            }
        }
        SceneObject o;
        o.name = "halfplane";
        ScalarField f;
        f.name = "value";
        for (const auto& p : poly) {
            o.vertices.insert(o.vertices.end(), {float(p[0]), float(p[1]), float(-h.depth), 0.0f});
            f.values.push_back(h.value + h.gradient * float(p[0]));
        }
        for (std::uint32_t i = 1; i + 1 < poly.size(); ++i) o.indices.insert(o.indices.end(), {0u, i, i + 1});
        o.fields.push_back(std::move(f));
        scene->objects.push_back(std::move(o));
    }
    return scene;
}

// Fraction of the unit pixel square [x, x+1] x [y, y+1] (pixel coordinates)
// on the side f(px, py) <= 0 of a line f = alpha px + beta py - gamma.
inline double squareCoverage(double alpha, double beta, double gamma, int x, int y) {
    std::vector<std::array<double, 2>> poly = {{double(x), double(y)}, {x + 1.0, double(y)},
                                               {x + 1.0, y + 1.0}, {double(x), y + 1.0}};
    std::vector<std::array<double, 2>> out;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const auto& p = poly[i];
        const auto& q = poly[(i + 1) % poly.size()];
        const double fp = alpha * p[0] + beta * p[1] - gamma, fq = alpha * q[0] + beta * q[1] - gamma;
        if (fp <= 0) out.push_back(p);
        if ((fp < 0) != (fq < 0) && fp != fq) {
            const double t = fp / (fp - fq);
            out.push_back({p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])});
        }
    }
    double area = 0;
    for (std::size_t i = 0; i < out.size(); ++i) {
        const auto& p = out[i];
        const auto& q = out[(i + 1) % out.size()];
        area += p[0] * q[1] - q[0] * p[1];
    }
    return std::abs(area) * 0.5;
}

// The world point on the plane z = -depth seen through continuous pixel
// coordinate (px, py).
inline void onPlane(const Camera& cam, double px, double py, double depth, double& x, double& y) {
    Vec3 o, d;
    cam.ray(px, py, o, d);
    const Vec3 p = o + d * depth;  // forward component of d is 1: t = planar depth
    x = p.x;
    y = p.y;
}

inline float at(const Buffer& b, const char* channel, int x, int y) {
    return b.hostFloat(channel)[std::size_t(y) * std::size_t(b.width()) + std::size_t(x)];
}

inline double maxAbsDiff(const Buffer& a, const Buffer& b, const std::vector<std::string>& channels) {
    double m = 0;
    for (const auto& c : channels) {
        const float* pa = a.requireFloat(c);
        const float* pb = b.requireFloat(c);
        for (std::size_t i = 0; i < a.pixelCount(); ++i) m = std::max(m, double(std::abs(pa[i] - pb[i])));
    }
    return m;
}

// RMSE over R, G, B (mean of the three channels' RMSEs, as the sweeps report).
inline double rgbRmse(const Buffer& a, const Buffer& b) {
    double sum = 0;
    for (const char* c : {"R", "G", "B"}) {
        const float* pa = a.requireFloat(c);
        const float* pb = b.requireFloat(c);
        double s = 0;
        for (std::size_t i = 0; i < a.pixelCount(); ++i) s += double(pa[i] - pb[i]) * double(pa[i] - pb[i]);
        sum += std::sqrt(s / double(a.pixelCount()));
    }
    return sum / 3.0;
}

// Every R, G, B, A value finite and in [0, 1] (with a float rounding slack).
inline void expectFiniteUnit(const Buffer& b, const std::string& what) {
    for (const char* c : {"R", "G", "B", "A"}) {
        const float* p = b.hostFloat(c);
        if (!p) continue;
        for (std::size_t i = 0; i < b.pixelCount(); ++i) {
            ASSERT_TRUE(std::isfinite(p[i]) && p[i] >= -1e-6f && p[i] <= 1.0f + 1e-6f)
                << what << ": " << c << "[" << i << "] = " << p[i];
        }
    }
}

}  // namespace darkroom::aatest
