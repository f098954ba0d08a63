#pragma once
// Scenes with known answers for the ray-traced references, built here so the
// reference tests do not depend on the stress-scene catalogue they validate
// the harness against.
#include <darkroom/capture_backend.h>
#include <darkroom/context.h>
#include <darkroom/core/registry.h>
#include <darkroom/core/run_filter.h>
#include <gtest/gtest.h>

#include "test_support.h"

#include <cmath>
#include <memory>

namespace darkroom::test {

// Two triangles spanning corner, corner + e1, corner + e1 + e2, corner + e2,
// with point field "u" running from 0 to 1 along e1.
inline SceneObject quad(Vec3 c, Vec3 e1, Vec3 e2) {
    SceneObject o;
    o.name = "quad";
    const Vec3 v[4] = {c, c + e1, c + e1 + e2, c + e2};
    for (const Vec3& p : v) o.vertices.insert(o.vertices.end(), {float(p.x), float(p.y), float(p.z), 0.0f});
    o.indices = {0, 1, 2, 0, 2, 3};
    o.fields.push_back({"u", ScalarField::Association::Point, {0.0f, 1.0f, 1.0f, 0.0f}});
    return o;
}

// Floor y = 0 and wall z = 0, each 200 x 100 units: infinite for radius 1.
inline std::shared_ptr<const Scene> cornerScene() {
    auto s = std::make_shared<Scene>();
    s->objects.push_back(quad({-100, 0, 0}, {200, 0, 0}, {0, 0, 100}));
    s->objects.push_back(quad({-100, 0, 0}, {0, 100, 0}, {200, 0, 0}));
    return s;
}

inline Camera lookAt(Vec3 from, Vec3 to, int w, int h, double fov = 40.0) {
    Camera c;
    c.position = from;
    c.forward = normalize(to - from);
    c.up = {0, 1, 0};
    c.fovYDegrees = fov;
    c.width = w;
    c.height = h;
    return c;
}

struct Embree {
    std::unique_ptr<CaptureBackend> backend;
    std::unique_ptr<Context> ctx;
    explicit Embree(std::shared_ptr<const Scene> scene, int threads = 2) {
        backend = pluginRegistry().createBackend("embree");
        if (!backend) throw std::runtime_error("the embree backend is not built");
        backend->setScene(std::move(scene));
        FilterRunOptions o;
        o.threads = threads;
        ctx = makeStandaloneContext(o, "reference-test");
    }
};

}  // namespace darkroom::test
