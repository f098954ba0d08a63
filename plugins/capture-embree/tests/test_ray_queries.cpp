// CaptureBackend::trace and ::occluded: arbitrary rays for ray-traced
// references, computed exactly as render() computes a pixel.
#include "render_helpers.h"
#include "scene_builders.h"

#include <darkroom/error.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace darkroom::test {
namespace {

struct Fixture {
    std::unique_ptr<CaptureBackend> backend = embreeBackend();
    std::unique_ptr<Context> ctx;
    explicit Fixture(std::vector<SceneObject> objects, int threads = 2) {
        backend->setScene(sceneOf(std::move(objects)));
        FilterRunOptions options;
        options.threads = threads;
        ctx = makeStandaloneContext(options, "ray-query-test");
    }
};

// A unit quad in the plane z = 0 spanning [0, 1]^2, with a point field
// "height" equal to x.
SceneObject unitQuad() {
    SceneObject q = makeQuad({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    ScalarField f;
    f.name = "height";
    for (std::size_t i = 0; i < q.vertexCount(); ++i) f.values.push_back(q.vertices[4 * i]);
    q.fields.push_back(f);
    return q;
}

TEST(RayQueries, TraceReportsTheRayParameterFieldsNormalsAndIdsPerRay) {
    Fixture f({unitQuad()});
    RayBatch rays;
    // Hit at t = 2 (direction length 2 => 4 world units away), a miss, and
    // a hit from behind whose normal must face back along the ray.
    rays.add({0.25, 0.5, 4}, {0, 0, -2});
    rays.add({5, 5, 4}, {0, 0, -1});
    rays.add({0.75, 0.5, -1}, {0, 0, 1});
    CaptureRequest req;
    req.scalars = {"height"};
    req.normals = true;
    req.objectId = true;
    const BufferPtr b = f.backend->trace(rays, req, *f.ctx);
    ASSERT_EQ(b->width(), 3);
    ASSERT_EQ(b->height(), 1);
    const float* z = b->requireFloat("Z");
    const float* h = b->requireFloat("height");
    const float* nz = b->requireFloat("N.z");
    const std::uint32_t* id = b->requireUInt("objectId");
    EXPECT_NEAR(z[0], 2.0f, 1e-5f);
    EXPECT_NEAR(h[0], 0.25f, 1e-5f);
    EXPECT_FLOAT_EQ(nz[0], 1.0f);
    EXPECT_EQ(id[0], 0u);
    EXPECT_TRUE(std::isinf(z[1]));
    EXPECT_TRUE(std::isnan(h[1]));
    EXPECT_EQ(id[1], ~0u);
    EXPECT_NEAR(z[2], 1.0f, 1e-5f);
    EXPECT_NEAR(h[2], 0.75f, 1e-5f);
    EXPECT_FLOAT_EQ(nz[2], -1.0f);
}

TEST(RayQueries, TraceOfPrimaryRaysEqualsRender) {
    Fixture f({makeSphereMesh({0, 0, 0}, 1.0, 24, 48), makePoints({{0.8, 0.8, 0.5}}, 0.3)});
    // Off-centre target: a pixel ray through the sphere's pole vertex could
    // pick either neighbouring triangle when rounded differently.
    const Camera cam = perspectiveCamera({0, 0, 5}, {0.013, 0.007, 0}, 37, 23);
    CaptureRequest req;
    req.normals = true;
    req.objectId = true;
    const BufferPtr image = f.backend->render(cam, req, *f.ctx);
    RayBatch rays;
    for (int y = 0; y < cam.height; ++y)
        for (int x = 0; x < cam.width; ++x) {
            Vec3 o, d;
            cam.ray(x + 0.5, y + 0.5, o, d);
            rays.add(o, d);
        }
    const BufferPtr traced = f.backend->trace(rays, req, *f.ctx);
    ASSERT_EQ(traced->pixelCount(), image->pixelCount());
    for (const char* c : {"Z", "N.x", "N.y", "N.z"}) {
        const float* a = image->requireFloat(c);
        const float* b = traced->requireFloat(c);
        for (std::size_t i = 0; i < image->pixelCount(); ++i) {
            if (std::isinf(a[i]) || std::isnan(a[i])) {
                EXPECT_EQ(std::isinf(a[i]), std::isinf(b[i])) << c << " at " << i;
                continue;
            }
            // Camera::ray and the backend's primary rays round differently
            // (double basis per ray vs once per image): a few ulps apart.
            EXPECT_NEAR(a[i], b[i], 1e-4f * std::max(1.0f, std::abs(a[i]))) << c << " at " << i;
        }
    }
    const std::uint32_t* ia = image->requireUInt("objectId");
    const std::uint32_t* ib = traced->requireUInt("objectId");
    std::size_t same = 0;
    for (std::size_t i = 0; i < image->pixelCount(); ++i) same += ia[i] == ib[i];
    EXPECT_EQ(same, image->pixelCount());
}

TEST(RayQueries, OccludedHonoursTheRayInterval) {
    Fixture f({unitQuad()});
    RayBatch rays;
    rays.tNear = 0.0f;
    rays.add({0.5, 0.5, 1}, {0, 0, -1}, 2.0f);    // quad at t = 1: occluded
    rays.add({0.5, 0.5, 1}, {0, 0, -1}, 0.5f);    // stops short: free
    rays.add({0.5, 0.5, 1}, {0, 0, 1}, 10.0f);    // points away: free
    rays.add({0.5, 0.5, 1}, {0, 0, -0.25}, 4.5f); // t = 4 in units of a short direction: occluded
    rays.add({2.0, 0.5, 1}, {0, 0, -1}, 2.0f);    // beside the quad: free
    std::vector<std::uint8_t> hit;
    f.backend->occluded(rays, hit, *f.ctx);
    EXPECT_THAT(hit, ::testing::ElementsAre(1, 0, 0, 1, 0));
}

TEST(RayQueries, OccludedAgreesWithTraceOnManyRays) {
    // 1000 rays of one batch (several packets, a partial last one) towards
    // random points around a sphere: occluded() and trace() must agree.
    Fixture f({makeSphereMesh({0, 0, 0}, 1.0, 16, 32), makeTube({-2, 1.2, 0}, {2, 1.2, 0}, 0.1, 1)});
    RayBatch rays;
    for (int i = 0; i < 1001; ++i) {
        const double a = 0.37 * i, b = 0.11 * i;
        const Vec3 target{1.5 * std::cos(a), 1.5 * std::sin(b), 0.5 * std::sin(a + b)};
        const Vec3 origin{0.3 * std::sin(b), 0.2, 6};
        rays.add(origin, target - origin, 1.0f);
    }
    std::vector<std::uint8_t> hit;
    f.backend->occluded(rays, hit, *f.ctx);
    const BufferPtr traced = f.backend->trace(rays, CaptureRequest{}, *f.ctx);
    const float* z = traced->requireFloat("Z");
    std::size_t hits = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        EXPECT_EQ(hit[i] == 1, z[i] < 1.0f) << "ray " << i << " t=" << z[i];
        hits += hit[i];
    }
    EXPECT_GT(hits, 100u);
    EXPECT_LT(hits, 1000u);
}

TEST(RayQueries, MalformedBatchesAreErrors) {
    Fixture f({unitQuad()});
    RayBatch rays;
    std::vector<std::uint8_t> hit;
    EXPECT_THAT([&] { f.backend->occluded(rays, hit, *f.ctx); },
                ::testing::ThrowsMessage<Error>(::testing::HasSubstr("1 to")));
    rays.add({0, 0, 1}, {0, 0, -1});
    rays.directions.pop_back();
    EXPECT_THAT([&] { f.backend->trace(rays, CaptureRequest{}, *f.ctx); },
                ::testing::ThrowsMessage<Error>(::testing::HasSubstr("3 of each per ray")));
    RayBatch far;
    far.add({0, 0, 1}, {0, 0, -1}, 1.0f);
    far.add({0, 0, 1}, {0, 0, -1});
    EXPECT_THAT([&] { f.backend->occluded(far, hit, *f.ctx); },
                ::testing::ThrowsMessage<Error>(::testing::HasSubstr("one per ray or none")));
}

}  // namespace
}  // namespace darkroom::test
