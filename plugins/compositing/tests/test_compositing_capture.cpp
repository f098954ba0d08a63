// The defining property of Compositing: merging separate captures of two
// objects equals capturing both in one scene, pixel for pixel.
#include "test_support.h"

#include <darkroom/capture_backend.h>
#include <darkroom/core/registry.h>
#include <darkroom/core/run_filter.h>
#include <darkroom/scene/generators.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

using namespace darkroom;

namespace {

BufferPtr capture(std::vector<SceneObject> objects, const Camera& camera, const CaptureRequest& request) {
    auto backend = test::pluginRegistry().createBackend("embree");
    EXPECT_TRUE(backend) << "the embree backend is not registered";
    auto scene = std::make_shared<Scene>();
    scene->objects = std::move(objects);
    backend->setScene(scene);
    FilterRunOptions options;
    options.threads = 2;
    auto ctx = makeStandaloneContext(options, "capture");
    return backend->render(camera, request, *ctx);
}

Camera obliqueCamera() {
    Camera c;
    c.position = {0.3, -3.2, 2.4};
    c.forward = normalize(Vec3{0, 0, -0.2} - c.position);
    c.up = {0, 0, 1};
    c.fovYDegrees = 40;
    c.width = 120;
    c.height = 90;
    return c;
}

// Same bits, or both NaN (captures write one NaN pattern, but do not rely on it).
bool sameFloat(float a, float b) {
    return (std::isnan(a) && std::isnan(b)) || std::memcmp(&a, &b, sizeof a) == 0;
}

void expectSameChannel(const Buffer& got, const Buffer& want, const std::string& name, const std::string& what) {
    const float* g = got.requireFloat(name);
    const float* w = want.requireFloat(name);
    int bad = 0;
    for (std::size_t i = 0; i < got.pixelCount(); ++i)
        if (!sameFloat(g[i], w[i]) && ++bad <= 5)
            ADD_FAILURE() << what << ": channel " << name << " pixel " << i << " composite " << g[i] << " capture "
                          << w[i];
    EXPECT_EQ(bad, 0) << what << ": " << name;
}

void checkEquality(const std::vector<SceneObject>& a, const std::vector<SceneObject>& b, const CaptureRequest& req,
                   const std::vector<std::string>& compared, const std::string& what) {
    const Camera cam = obliqueCamera();
    std::vector<SceneObject> both = a;
    both.insert(both.end(), b.begin(), b.end());
    const BufferPtr ca = capture(a, cam, req), cb = capture(b, cam, req), cab = capture(both, cam, req);

    auto f = test::pluginRegistry().createFilter("Compositing");
    const BufferPtr merged = runFilter(*f, {{"images", {Value(ca), Value(cb)}}}).outputs.at("image").asImage();
    ASSERT_EQ(merged->width(), cab->width());
    ASSERT_EQ(merged->height(), cab->height());
    EXPECT_EQ(merged->metadata().camera, cab->metadata().camera);

    // Both objects must really appear, and overlap, or the test proves little.
    std::size_t fromA = 0, fromB = 0, bAheadOfA = 0;
    const float* za = ca->hostFloat("Z");
    const float* zb = cb->hostFloat("Z");
    for (std::size_t i = 0; i < ca->pixelCount(); ++i) {
        fromA += std::isfinite(za[i]) && !(zb[i] < za[i]);
        fromB += zb[i] < za[i];
        bAheadOfA += std::isfinite(za[i]) && zb[i] < za[i];
    }
    EXPECT_GT(fromA, 100u) << what;
    EXPECT_GT(fromB, 100u) << what;
    EXPECT_GT(bAheadOfA, 20u) << what;
    for (const auto& c : compared) expectSameChannel(*merged, *cab, c, what);
}

}  // namespace

TEST(CompositingCapture, FloorAndParticlesEqualOneCapture) {
    // Both carry `height` (the plane) or `value` (the particles); each object
    // gets NaN for the field it lacks in every capture, so both are comparable.
    auto plane = generate("plane", {{"size", "3"}, {"center", "0 0 -1.1"}});
    auto particles = generate("particles", {{"count", "400"}, {"radius", "0.04"}});
    CaptureRequest req;
    req.scalars = {"height", "value"};
    req.normals = true;
    checkEquality(plane, particles, req, {"Z", "height", "value", "N.x", "N.y", "N.z"}, "plane + particles");
}

TEST(CompositingCapture, TwoIsosurfacesEqualOneCapture) {
    // Two level sets of the same field, the second moved aside and towards
    // the camera so that each hides part of the other.
    auto outer = generate("isosurface", {{"resolution", "40"}, {"isovalue", "0.6"}});
    auto inner = generate("isosurface", {{"resolution", "40"}, {"isovalue", "0.3"}});
    for (std::size_t i = 0; i < inner[0].vertices.size(); i += 4) {
        inner[0].vertices[i] += 1.1f;
        inner[0].vertices[i + 1] -= 0.9f;
    }
    CaptureRequest req;
    req.scalars = {"field", "height"};
    req.normals = true;
    checkEquality(outer, inner, req, {"Z", "field", "height", "N.x", "N.y", "N.z"}, "two isosurfaces");
}
