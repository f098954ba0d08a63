// Normals: known answers on analytic planes and steps, pass-through, stress inputs.
#include "depth_scenes.h"
#include "simd_targets.h"

#include <darkroom/error.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

using namespace darkroom;
using namespace darkroom::test;
using ::testing::HasSubstr;

namespace {

const float kInf = std::numeric_limits<float>::infinity();
const float kNaN = std::numeric_limits<float>::quiet_NaN();
const ScenePlane kTilted{{0, 0, 0}, normalize(Vec3{0.3, -0.2, 1.0})};

void expectVecNear(const Vec3& got, const Vec3& want, double tol, const std::string& what) {
    EXPECT_NEAR(got.x, want.x, tol) << what;
    EXPECT_NEAR(got.y, want.y, tol) << what;
    EXPECT_NEAR(got.z, want.z, tol) << what;
}

// The plane normal expressed in the view space of the Normals pass.
Vec3 toView(const Camera& c, const Vec3& n) {
    Vec3 r, u, f;
    c.basis(r, u, f);
    return {dot(n, r), dot(n, u), -dot(n, f)};
}

class PlaneNormals : public ::testing::TestWithParam<std::tuple<bool, std::string>> {};

TEST_P(PlaneNormals, AreExactEverywhereAndPositionsMatchTheRays) {
    const auto [perspective, method] = GetParam();
    const Camera cam = viewCamera(32, 24, perspective);
    const BufferPtr out = runPass("Normals", depthImage(cam, [&](int x, int y) { return planeDepth(cam, kTilted, x, y); }),
                                  {{"method", {Value(method)}}});
    const Vec3 want = facing(cam, kTilted);
    for (int y = 0; y < cam.height; ++y)
        for (int x = 0; x < cam.width; ++x) {
            const std::size_t i = std::size_t(y) * cam.width + x;
            const std::string at = method + " pixel " + std::to_string(x) + "," + std::to_string(y);
            expectVecNear(vec(*out, "N", i), want, 1e-3, at);
            expectVecNear(vec(*out, "Nv", i), toView(cam, want), 1e-3, at);
            const Vec3 p = cam.worldPosition(x + 0.5, y + 0.5, planeDepth(cam, kTilted, x, y));
            expectVecNear(vec(*out, "P", i), p, 1e-5 * (1 + length(p - cam.position)), at);
            EXPECT_NEAR(dot(vec(*out, "P", i) - kTilted.point, kTilted.normal), 0.0, 1e-4) << at;
        }
}

INSTANTIATE_TEST_SUITE_P(AllMethodsAndProjections, PlaneNormals,
                         ::testing::Combine(::testing::Bool(), ::testing::Values("central", "nearest", "extrapolated")));

// Two parallel tilted planes, the far one 1.5 units behind, split at column
// (or row) `split`: every pixel lies on one plane, so the true normal is known
// everywhere, including next to the discontinuity.
BufferPtr stepImage(const Camera& cam, bool alongX, int split) {
    const ScenePlane far{{0, 0, -1.5}, kTilted.normal};
    return depthImage(cam, [&, alongX, split](int x, int y) {
        return planeDepth(cam, (alongX ? x : y) < split ? kTilted : far, x, y);
    });
}

class StepNormals : public ::testing::TestWithParam<std::tuple<bool, bool>> {};

TEST_P(StepNormals, DiscontinuityAwareMethodsAreExactOnBothSidesCentralIsNot) {
    const auto [perspective, alongX] = GetParam();
    const Camera cam = viewCamera(32, 24, perspective);
    const int split = alongX ? 16 : 12;
    const BufferPtr img = stepImage(cam, alongX, split);
    const Vec3 want = facing(cam, kTilted);
    for (const std::string method : {"nearest", "extrapolated"}) {
        const BufferPtr out = runPass("Normals", img, {{"method", {Value(method)}}});
        for (std::size_t i = 0; i < out->pixelCount(); ++i)
            expectVecNear(vec(*out, "N", i), want, 1e-3, method + " pixel " + std::to_string(i));
    }
    const BufferPtr central = runPass("Normals", img, {{"method", {Value("central")}}});
    for (int y = 0; y < cam.height; ++y)
        for (int x = 0; x < cam.width; ++x) {
            const std::size_t i = std::size_t(y) * cam.width + x;
            const int c = alongX ? x : y;
            const double err = angleDegrees(vec(*central, "N", i), want);
            if (c == split - 1 || c == split)
                EXPECT_GT(err, 10.0) << "central difference straddles the step at " << x << "," << y;
            else
                EXPECT_LT(err, 0.06) << x << "," << y;
        }
}

INSTANTIATE_TEST_SUITE_P(Projections, StepNormals, ::testing::Combine(::testing::Bool(), ::testing::Bool()));

TEST(Normals, PassesEveryChannelThroughAndKeepsCapturedNormalsUnlessReplaced) {
    const Camera cam = viewCamera(8, 6, true);
    auto img = depthImage(cam, [&](int x, int y) { return planeDepth(cam, kTilted, x, y); }, {"R", "N.x", "N.y", "N.z"});
    // Deliberately wrong "captured" normals (0, 0, 1) to tell them apart.
    std::fill_n(img->writeFloat("N.x"), img->pixelCount(), 0.0f);
    std::fill_n(img->writeFloat("N.y"), img->pixelCount(), 0.0f);
    std::fill_n(img->writeFloat("N.z"), img->pixelCount(), 1.0f);
    const BufferPtr kept = runPass("Normals", img);
    EXPECT_EQ(kept->metadata(), img->metadata());
    for (std::size_t i = 0; i < img->pixelCount(); ++i) {
        EXPECT_EQ(kept->hostFloat("R")[i], 0.5f);
        EXPECT_EQ(kept->hostFloat("Z")[i], img->hostFloat("Z")[i]);
        expectVecNear(vec(*kept, "N", i), {0, 0, 1}, 0, "kept");
        expectVecNear(vec(*kept, "Nv", i), toView(cam, {0, 0, 1}), 1e-6, "Nv follows the kept N");
    }
    const BufferPtr replaced = runPass("Normals", img, {{"replace", {Value(true)}}});
    for (std::size_t i = 0; i < img->pixelCount(); ++i) expectVecNear(vec(*replaced, "N", i), facing(cam, kTilted), 1e-3, "replaced");
}

TEST(Normals, UInt32ChannelsPassThrough) {
    const Camera cam = viewCamera(4, 3, true);
    std::vector<ChannelDesc> ch{{"Z"}, {"objectId", ChannelType::UInt32}};
    auto img = makeCpuBuffer(4, 3, ch);
    img->metadata().camera = cam;
    for (std::size_t i = 0; i < 12; ++i) {
        img->writeFloat("Z")[i] = 4.0f;
        img->writeUInt("objectId")[i] = std::uint32_t(i * 7);
    }
    const BufferPtr out = runPass("Normals", img);
    for (std::size_t i = 0; i < 12; ++i) EXPECT_EQ(out->hostUInt("objectId")[i], i * 7);
}

// Without a camera a plane of constant depth is shaded in image space
// (docs/cameras.md): it faces the viewer.
TEST(Normals, WithoutCameraAFlatImageFacesTheViewer) {
    auto img = makeImage(4, 4, {"Z"}, [](int, int, int) { return 3.0f; });
    const BufferPtr out = runPass("Normals", img);
    const float* nz = out->requireFloat("Nv.z");
    for (std::size_t i = 0; i < out->pixelCount(); ++i) EXPECT_NEAR(nz[i], 1.0f, 1e-6f) << i;
}

TEST(Normals, MissingDepthIsAnError) {
    auto img = makeImage(4, 4, {"R"}, [](int, int, int) { return 3.0f; });
    img->metadata().camera = viewCamera(4, 4, true);
    EXPECT_THROW(runPass("Normals", img), Error);
}

TEST(Normals, BackgroundNaNAndInfinitiesGiveNaNThereAndUnitNormalsElsewhere) {
    const Camera cam = viewCamera(9, 7, true);
    auto img = depthImage(cam, [&](int x, int y) {
        if (x == 4 && y == 3) return double(kNaN);
        if (x == 2 && y == 2) return -double(kInf);
        if (x == 6 && y == 4) return double(kInf);  // every other pixel keeps a neighbour per axis
        return planeDepth(cam, kTilted, x, y);
    });
    const BufferPtr out = runPass("Normals", img);
    for (std::size_t i = 0; i < out->pixelCount(); ++i) {
        const bool hole = !std::isfinite(img->hostFloat("Z")[i]);
        for (const char* c : {"N.x", "N.y", "N.z", "Nv.x", "Nv.y", "Nv.z", "P.x", "P.y", "P.z"})
            EXPECT_EQ(std::isnan(out->hostFloat(c)[i]), hole) << c << " pixel " << i;
        if (!hole) {
            EXPECT_NEAR(length(vec(*out, "N", i)), 1.0, 1e-5);
            // Holes only remove neighbours: the plane is still found exactly.
            expectVecNear(vec(*out, "N", i), facing(cam, kTilted), 1e-3, "pixel " + std::to_string(i));
        }
    }
}

TEST(Normals, AllBackgroundAndOnePixelImages) {
    for (const bool perspective : {true, false}) {
        const Camera big = viewCamera(6, 5, perspective);
        const BufferPtr bg = runPass("Normals", depthImage(big, [](int, int) { return double(kInf); }));
        for (std::size_t i = 0; i < bg->pixelCount(); ++i) EXPECT_TRUE(std::isnan(bg->hostFloat("N.x")[i]));

        const Camera one = viewCamera(1, 1, perspective);
        const BufferPtr px = runPass("Normals", depthImage(one, [](int, int) { return 4.0; }));
        // No neighbour: the normal faces the viewer.
        const Vec3 n = vec(*px, "N", 0);
        EXPECT_NEAR(length(n), 1.0, 1e-6);
        Vec3 o, d;
        one.ray(0.5, 0.5, o, d);
        EXPECT_NEAR(dot(n, normalize(d)), -1.0, 1e-6);
    }
}

TEST(Normals, ResultDoesNotDependOnTheThreadCount) {
    const Camera cam = viewCamera(64, 48, true);
    const BufferPtr img = stepImage(cam, true, 20);
    for (const std::string m : {"central", "nearest", "extrapolated"}) {
        const BufferPtr a = runPass("Normals", img, {{"method", {Value(m)}}}, 1);
        const BufferPtr b = runPass("Normals", img, {{"method", {Value(m)}}}, 4);
        EXPECT_TRUE(identical(*a, *b)) << m;
    }
}

// The reconstruction runs vectors of pixels with the best SIMD instructions
// of the CPU (the image's first and last two columns, and a row's remainder
// shorter than a vector, pixel by pixel): every instruction set gives the
// same bits, on steps, holes and both projections.
TEST(Normals, ResultDoesNotDependOnTheSimdInstructionSet) {
    for (const bool perspective : {true, false}) {
        const Camera cam = viewCamera(67, 45, perspective);
        const ScenePlane far{{0, 0, -1.5}, kTilted.normal};
        const BufferPtr in = depthImage(cam, [&](int x, int y) {
            const int i = y * cam.width + x;
            if (i % 37 == 0) return i % 3 ? double(kInf) : (i % 2 ? double(kNaN) : -double(kInf));
            return planeDepth(cam, x < 30 ? kTilted : far, x, y);
        });
        for (const std::string m : {"central", "nearest", "extrapolated"}) {
            const auto results = resultsPerSimdTarget([&] { return runPass("Normals", in, {{"method", {Value(m)}}}); });
            ASSERT_FALSE(results.empty());
            for (const auto& [target, out] : results)
                EXPECT_TRUE(identical(*out, *results.front().second))
                    << m << (perspective ? " perspective: " : " orthographic: ") << target << " differs from "
                    << results.front().first;
        }
    }
}

}  // namespace
