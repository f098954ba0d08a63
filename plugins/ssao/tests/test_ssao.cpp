// SSAO: robustness (background, 1x1, NaN/inf, particles), pass-through,
// determinism (thread count, SIMD target), the points geometry's halo
// removal, half resolution at silhouettes, and errors.
#include "analytic_scenes.h"

#include <darkroom/capture_backend.h>
#include <darkroom/error.h>
#include <darkroom/core/registry.h>
#include <darkroom/core/run_filter.h>
#include <darkroom/scene/generators.h>

#include <gmock/gmock.h>
#include <hwy/targets.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace darkroom;
using namespace ssao_test;
using ::testing::HasSubstr;

namespace {

using Inputs = std::map<std::string, std::vector<Value>>;
const float kInf = std::numeric_limits<float>::infinity();
const float kNaN = std::numeric_limits<float>::quiet_NaN();

BufferPtr runSsao(const BufferPtr& image, Inputs params = {}, int threads = 2) {
    auto f = test::pluginRegistry().createFilter("SSAO");
    params["image"] = {Value(image)};
    FilterRunOptions o;
    o.threads = threads;
    return runFilter(*f, params, o).outputs.at("image").asImage();
}

// Every combination of method, geometry mode and resolution.
std::vector<Inputs> allModes() {
    std::vector<Inputs> modes;
    for (const char* m : {"hemisphere", "horizon"})
        for (const char* g : {"surface", "points"})
            for (const char* r : {"full", "half"})
                modes.push_back({{"method", {Value(m)}}, {"geometry", {Value(g)}}, {"resolution", {Value(r)}}});
    return modes;
}

std::string describe(const Inputs& p) {
    return p.at("method")[0].asString() + "/" + p.at("geometry")[0].asString() + "/" +
           p.at("resolution")[0].asString();
}

// AO finite and in [0, 1] everywhere, exactly 1 where depth is not a valid
// point in front of the camera.
void expectBoundedAO(const Buffer& out, const std::string& what) {
    const float* ao = out.requireFloat("AO");
    const float* z = out.requireFloat("Z");
    for (std::size_t i = 0; i < out.pixelCount(); ++i) {
        ASSERT_TRUE(std::isfinite(ao[i]) && ao[i] >= 0.0f && ao[i] <= 1.0f) << what << " pixel " << i << ": " << ao[i];
        if (!std::isfinite(z[i])) {
            ASSERT_EQ(ao[i], 1.0f) << what << " pixel " << i;
        }
    }
}

BufferPtr particleCapture(int size) {
    auto backend = test::pluginRegistry().createBackend("embree");
    auto scene = std::make_shared<Scene>();
    scene->objects = generate("particles", {{"count", "800"}, {"radius", "0.03"}});
    backend->setScene(scene);
    auto ctx = makeStandaloneContext({});
    return backend->render(lookAt({0, 0.4, 3.6}, {0, 0, 0}, size, size), {}, *ctx);
}

}  // namespace

TEST(Ssao, AllBackgroundGivesOne) {
    auto img = test::makeImage(7, 5, {"Z", "R"}, [](int, int, int c) { return c == 0 ? kInf : 0.5f; });
    img->metadata().camera = lookAt({0, 0, 5}, {0, 0, 0}, 7, 5);
    for (const auto& mode : allModes()) {
        const BufferPtr out = runSsao(img, mode);
        expectBoundedAO(*out, describe(mode));
        EXPECT_EQ(out->hostFloat("R")[3], 0.5f);
    }
}

TEST(Ssao, OnePixelImageIsFiniteAndUnoccluded) {
    auto img = test::makeImage(1, 1, {"Z"}, [](int, int, int) { return 3.0f; });
    img->metadata().camera = lookAt({0, 0, 5}, {0, 0, 0}, 1, 1);
    for (const auto& mode : allModes()) {
        const BufferPtr out = runSsao(img, mode);
        expectBoundedAO(*out, describe(mode));
        // No neighbour can occlude a lone pixel.
        EXPECT_EQ(out->hostFloat("AO")[0], 1.0f) << describe(mode);
    }
}

TEST(Ssao, NonFiniteAndNonPositiveDepthsStayBounded) {
    // A bumpy surface salted with NaN, +inf, -inf, zero and negative depths.
    auto img = test::makeImage(48, 40, {"Z"}, [](int x, int y, int) {
        switch ((x * 7 + y * 13) % 11) {
            case 0: return kNaN;
            case 1: return kInf;
            case 2: return -kInf;
            case 3: return 0.0f;
            case 4: return -1.0f;
            default: return 4.0f + 0.3f * std::sin(0.5f * float(x)) * std::cos(0.4f * float(y));
        }
    });
    img->metadata().camera = lookAt({0, 0, 5}, {0, 0, 0}, 48, 40);
    for (auto mode : allModes()) {
        mode["radius"] = {Value(0.2)};
        const BufferPtr out = runSsao(img, mode);
        expectBoundedAO(*out, describe(mode));
        const float* z = out->hostFloat("Z");
        for (std::size_t i = 0; i < out->pixelCount(); ++i)
            if (!(z[i] > 0)) {
                EXPECT_EQ(out->hostFloat("AO")[i], 1.0f) << "pixel " << i << " Z " << z[i];
            }
    }
}

TEST(Ssao, ParticlesStayBoundedAndBackgroundIsOne) {
    const BufferPtr cap = particleCapture(96);
    for (const auto& mode : allModes()) expectBoundedAO(*runSsao(cap, mode), describe(mode));
}

TEST(Ssao, OneAndFourThreadsGiveIdenticalBuffers) {
    const Camera cam = lookAt({3.2, 2.6, 3.5}, {0.6, 0.2, 0}, 90, 70, 50);
    const auto z = depthImage(cam, cornerHit);
    for (const auto& mode : allModes()) {
        const BufferPtr one = runSsao(z, mode, 1);
        const BufferPtr four = runSsao(z, mode, 4);
        EXPECT_TRUE(identical(*one, *four)) << describe(mode);
    }
}

// The kernels are compiled for AVX2 and AVX-512 and chosen at run time; both
// must give the same bits, or pinned pictures would depend on the CPU.
TEST(Ssao, Avx2AndAvx512GiveIdenticalBuffers) {
    const std::int64_t supported = hwy::SupportedTargets();
    if (!(supported & HWY_AVX3) || !(supported & HWY_AVX2)) GTEST_SKIP() << "this CPU lacks AVX-512 or AVX2";
    const Camera cam = lookAt({3.2, 2.6, 3.5}, {0.6, 0.2, 0}, 90, 70, 50);
    const auto z = depthImage(cam, cornerHit);
    for (auto mode : allModes()) {
        mode["falloff"] = {Value(0.3)};  // both weight regimes
        hwy::SetSupportedTargetsForTest(HWY_AVX3 | HWY_AVX2);
        const BufferPtr wide = runSsao(z, mode);
        hwy::SetSupportedTargetsForTest(HWY_AVX2);
        const BufferPtr narrow = runSsao(z, mode);
        hwy::SetSupportedTargetsForTest(0);
        EXPECT_TRUE(identical(*wide, *narrow)) << describe(mode);
    }
}

TEST(Ssao, PassesEveryChannelThroughAndAddsAO) {
    auto img = test::makeImage(6, 4, {"Z", "R", "G", "B", "A", "value"},
                               [](int x, int y, int c) { return c == 0 ? 2.0f + 0.1f * x : 0.1f * float(x + y + c); });
    img->metadata().camera = lookAt({0, 0, 5}, {0, 0, 0}, 6, 4);
    const BufferPtr out = runSsao(img);
    EXPECT_EQ(out->channelNames(), (std::vector<std::string>{"Z", "R", "G", "B", "A", "value", "AO"}));
    for (const auto& name : img->channelNames())
        for (std::size_t i = 0; i < img->pixelCount(); ++i)
            ASSERT_EQ(out->hostFloat(name)[i], img->hostFloat(name)[i]) << name;
    EXPECT_EQ(out->metadata(), img->metadata());
    // An existing AO channel is replaced, not duplicated.
    const BufferPtr again = runSsao(out);
    EXPECT_EQ(again->channelNames(), out->channelNames());
}

// A sphere floating `gap` in front of a wall, occlusion radius 0.5.
BufferPtr wallAO(double gap, const char* method, const char* geometry, double r = 0.2) {
    const Camera cam = lookAt({0, 0, 6}, {0, 0, 0}, 120, 120, 30);
    const auto z = depthImage(cam, [gap, r](const Vec3& o, const Vec3& d) {
        return std::min(sphereHit(o, d, {0, 0, gap + r}, r), planeHit(o, d, {0, 0, 0}, {0, 0, 1}));
    });
    return runSsao(z, {{"method", {Value(method)}},
                       {"geometry", {Value(geometry)}},
                       {"radiusUnits", {Value("world")}},
                       {"radius", {Value(0.5)}},
                       {"thickness", {Value(0.2)}}});
}

float lowestWallAO(const Buffer& out) {
    float lowest = 1;
    for (std::size_t i = 0; i < out.pixelCount(); ++i)
        if (out.hostFloat("Z")[i] > 5.9f) lowest = std::min(lowest, out.hostFloat("AO")[i]);
    return lowest;
}

TEST(Ssao, ParticleFartherThanTheRadiusDoesNotDarkenTheWall) {
    // Gap 0.6 > radius: every wall point is farther than 0.5 from the sphere,
    // so ray-traced AO on the wall is exactly 1, for both geometry modes.
    for (const char* method : {"hemisphere", "horizon"})
        for (const char* geometry : {"surface", "points"})
            EXPECT_GE(lowestWallAO(*wallAO(0.6, method, geometry)), 0.98f) << method << "/" << geometry;
}

TEST(Ssao, PointsGeometryIgnoresOccludersBeyondTheThickness) {
    // A sphere of radius 0.1 with gap 0.15 < radius: surface SSAO takes it for
    // the top of a solid column down to the wall and darkens a ring around its
    // silhouette (the halo). In points mode every visible point of the sphere
    // is at least 0.25 in front of the wall, more than thickness 0.2 x 0.5, so
    // by construction it occludes nothing there. (Ray-traced AO lies in between: the real sphere casts a faint
    // contact shadow that the points mode gives up.)
    for (const char* method : {"hemisphere", "horizon"}) {
        EXPECT_GE(lowestWallAO(*wallAO(0.15, method, "points", 0.1)), 0.999f) << method;
        EXPECT_LT(lowestWallAO(*wallAO(0.15, method, "surface", 0.1)), 0.95f) << method;
    }
}

// Half resolution fills a pixel only from computed neighbours on its own
// surface: next to a silhouette, where occlusion jumps (a sphere 0.15 in front
// of a wall darkens the wall around it, its own rim stays light), the wall
// keeps the occlusion full resolution gives it, instead of the mix a plain
// upsampling would make.
TEST(Ssao, HalfResolutionDoesNotBleedAcrossSilhouettes) {
    const Camera cam = lookAt({0, 0, 6}, {0, 0, 0}, 160, 160, 30);
    const auto z = depthImage(cam, [](const Vec3& o, const Vec3& d) {
        return std::min(sphereHit(o, d, {0, 0, 0.65}, 0.5), planeHit(o, d, {0, 0, 0}, {0, 0, 1}));
    });
    Inputs p{{"method", {Value("horizon")}},   {"radiusUnits", {Value("world")}}, {"radius", {Value(1.0)}},
             {"slices", {Value(std::int64_t(8))}}, {"steps", {Value(std::int64_t(16))}}, {"blurRadius", {Value(0)}},
             {"resolution", {Value("full")}}};
    const BufferPtr full = runSsao(z, p);
    p["resolution"] = {Value("half")};
    const BufferPtr half = runSsao(z, p);
    // Wall pixels with a sphere pixel among their 8 neighbours, and those
    // sphere pixels.
    const float* depth = z->hostFloat("Z");
    auto wall = [&](int x, int y) { return depth[std::size_t(y) * 160 + x] > 5.9f; };
    double fullWall = 0, halfWall = 0, fullRim = 0, halfRim = 0;
    int walls = 0, rims = 0;
    for (int y = 1; y < 159; ++y)
        for (int x = 1; x < 159; ++x) {
            bool mixed = false;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) mixed = mixed || wall(x + dx, y + dy) != wall(x, y);
            if (!mixed) continue;
            const std::size_t i = std::size_t(y) * 160 + x;
            const float f = full->hostFloat("AO")[i], h = half->hostFloat("AO")[i];
            if (wall(x, y)) fullWall += f, halfWall += h, ++walls;
            else fullRim += f, halfRim += h, ++rims;
        }
    ASSERT_GT(walls, 100);
    ASSERT_GT(rims, 100);
    fullWall /= walls, halfWall /= walls, fullRim /= rims, halfRim /= rims;
    std::printf("[silhouette] wall ring AO: full %.4f half %.4f; sphere rim: full %.4f half %.4f\n", fullWall, halfWall,
                fullRim, halfRim);
    // The jump is large, so a mix would show.
    ASSERT_GT(fullRim - fullWall, 0.2);
    EXPECT_NEAR(halfWall, fullWall, 0.02);
    EXPECT_NEAR(halfRim, fullRim, 0.02);
}

// Without a camera: image space (test_ssao_no_camera.cpp); without Z: an error.
TEST(Ssao, MissingDepthIsAnErrorAndMissingCameraIsNot) {
    auto noCamera = test::makeImage(3, 3, {"Z"}, [](int, int, int) { return 0.5f; });
    EXPECT_NO_THROW(runSsao(noCamera));
    auto noDepth = test::makeImage(3, 3, {"R"}, [](int, int, int) { return 1.0f; });
    noDepth->metadata().camera = lookAt({0, 0, 5}, {0, 0, 0}, 3, 3);
    try {
        runSsao(noDepth);
        FAIL() << "an image without Z must be refused";
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("Z"));
    }
}
