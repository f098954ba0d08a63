// IBS: no outlines on a plane, outlines exactly next to depth and id
// discontinuities on the chosen side, colour over, lighting, stress inputs.
#include "../../normals/tests/depth_scenes.h"
#include "../../normals/tests/simd_targets.h"

#include <darkroom/error.h>

#include <gtest/gtest.h>

using namespace darkroom;
using namespace darkroom::test;

namespace {

const float kInf = std::numeric_limits<float>::infinity();
const float kNaN = std::numeric_limits<float>::quiet_NaN();

float at(const BufferPtr& b, const char* c, int x, int y) { return b->hostFloat(c)[std::size_t(y) * b->width() + x]; }

void expectInRange(const Buffer& b) {
    for (const auto& c : b.channels()) {
        if (c.type != ChannelType::Float32 || c.name == "Z") continue;
        const float* p = b.hostFloat(c.name);
        for (std::size_t i = 0; i < b.pixelCount(); ++i) ASSERT_TRUE(std::isfinite(p[i])) << c.name << " " << i;
    }
    const float* s = b.hostFloat("Silhouette");
    for (std::size_t i = 0; i < b.pixelCount(); ++i) ASSERT_TRUE(s[i] == 0.0f || s[i] == 1.0f) << i;
}

TEST(Ibs, TiltedPlaneHasNoSilhouetteAndKeepsItsColour) {
    const ScenePlane plane{{0, 0, 0}, normalize(Vec3{0.3, -0.2, 1.0})};
    for (const bool perspective : {true, false}) {
        const Camera cam = viewCamera(32, 24, perspective);
        const BufferPtr img = depthImage(cam, [&](int x, int y) { return planeDepth(cam, plane, x, y); }, {"R", "G", "B", "A"});
        const BufferPtr out = runPass("IBS", img, {{"width", {Value(3.0)}}});
        expectInRange(*out);
        for (std::size_t i = 0; i < out->pixelCount(); ++i) {
            EXPECT_EQ(out->hostFloat("Silhouette")[i], 0.0f) << i;
            EXPECT_EQ(out->hostFloat("R")[i], 0.5f);
            EXPECT_EQ(out->hostFloat("A")[i], 0.5f);
        }
    }
}

// Near (Z = 4) left of `split`, far (Z = 6) from `split` on, along x or y.
BufferPtr step(bool alongX, int split, std::vector<std::string> extra = {"R", "G", "B", "A"}) {
    return depthImage(viewCamera(20, 16, true), [=](int x, int y) { return (alongX ? x : y) < split ? 4.0 : 6.0; }, extra);
}

TEST(Ibs, DepthStepIsOutlinedExactlyOnTheChosenSide) {
    for (const bool alongX : {true, false}) {
        const int split = 9;
        const BufferPtr img = step(alongX, split);
        struct Case { std::string side; double width; int first, last; };
        for (const Case& c : {Case{"near", 1.0, split - 1, split - 1}, Case{"far", 1.0, split, split},
                              Case{"near", 2.0, split - 2, split - 1}, Case{"far", 3.0, split, split + 2}}) {
            const BufferPtr out = runPass("IBS", img, {{"side", {Value(c.side)}}, {"width", {Value(c.width)}}});
            expectInRange(*out);
            for (int y = 0; y < 16; ++y)
                for (int x = 0; x < 20; ++x) {
                    const int k = alongX ? x : y;
                    EXPECT_EQ(at(out, "Silhouette", x, y), (k >= c.first && k <= c.last) ? 1.0f : 0.0f)
                        << c.side << " width " << c.width << " at " << x << "," << y;
                }
        }
    }
}

TEST(Ibs, SmallRelativeJumpsBelowTheThresholdAreNotEdges) {
    const BufferPtr img = depthImage(viewCamera(10, 4, true), [](int x, int) { return x < 5 ? 4.0 : 4.1; });  // 2.5 %
    EXPECT_EQ(runPass("IBS", img)->hostFloat("Silhouette")[4], 0.0f);
    EXPECT_EQ(runPass("IBS", img, {{"depthThreshold", {Value(0.02)}}})->hostFloat("Silhouette")[4], 1.0f);
}

TEST(Ibs, ObjectIdEdgeWithoutDepthEdgeIsDetected) {
    const Camera cam = viewCamera(10, 4, true);
    auto img = makeCpuBuffer(10, 4, {{"Z"}, {"objectId", ChannelType::UInt32}});
    img->metadata().camera = cam;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 10; ++x) {
            img->writeFloat("Z")[std::size_t(y) * 10 + x] = 4.0f;
            img->writeUInt("objectId")[std::size_t(y) * 10 + x] = x < 6 ? 1u : 2u;
        }
    const BufferPtr out = runPass("IBS", img);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 10; ++x)
            // Equal depths: the pixel with the lower id is the near side.
            EXPECT_EQ(at(out, "Silhouette", x, y), x == 5 ? 1.0f : 0.0f) << x << "," << y;
    const BufferPtr off = runPass("IBS", img, {{"objectIds", {Value(false)}}});
    for (std::size_t i = 0; i < 40; ++i) EXPECT_EQ(off->hostFloat("Silhouette")[i], 0.0f);
    for (std::size_t i = 0; i < 40; ++i) EXPECT_EQ(out->hostUInt("objectId")[i], img->hostUInt("objectId")[i]);
}

TEST(Ibs, OutlineColourIsCompositedOverWithStrength) {
    const BufferPtr img = step(true, 9, {"R", "G", "B"});
    const Inputs red{{"color", {Value(Color{1, 0, 0, 1})}}, {"strength", {Value(0.25)}}};
    const BufferPtr out = runPass("IBS", img, red);
    EXPECT_FLOAT_EQ(at(out, "R", 8, 3), 0.25f * 1.0f + 0.75f * 0.5f);
    EXPECT_FLOAT_EQ(at(out, "G", 8, 3), 0.75f * 0.5f);
    EXPECT_FLOAT_EQ(at(out, "R", 7, 3), 0.5f);
    EXPECT_FALSE(out->hasChannel("A")) << "no alpha is invented";
}

TEST(Ibs, FarSideOnBackgroundRaisesAlphaNearSideLeavesBackgroundAlone) {
    const Camera cam = viewCamera(12, 12, true);
    auto img = depthImage(cam, [](int x, int y) { return x >= 4 && x < 8 && y >= 4 && y < 8 ? 3.0 : double(kInf); },
                          {"R", "G", "B", "A"});
    for (std::size_t i = 0; i < img->pixelCount(); ++i)
        if (std::isinf(img->hostFloat("Z")[i])) img->writeFloat("A")[i] = 0.0f;
    const BufferPtr near = runPass("IBS", img);
    const BufferPtr far = runPass("IBS", img, {{"side", {Value("far")}}, {"color", {Value(Color{0, 0, 1, 1})}}});
    for (int y = 0; y < 12; ++y)
        for (int x = 0; x < 12; ++x) {
            const bool inside = x >= 4 && x < 8 && y >= 4 && y < 8;
            const bool ring = !inside && x >= 3 && x < 9 && y >= 3 && y < 9 && !((x == 3 || x == 8) && (y == 3 || y == 8));
            EXPECT_EQ(at(far, "Silhouette", x, y), ring ? 1.0f : 0.0f) << x << "," << y;
            EXPECT_EQ(at(far, "A", x, y), inside ? 0.5f : (ring ? 1.0f : 0.0f)) << x << "," << y;
            if (ring) {
                EXPECT_EQ(at(far, "B", x, y), 1.0f);
            }
            if (!inside) {
                EXPECT_EQ(at(near, "A", x, y), 0.0f);
            }
        }
}

TEST(Ibs, HeadlightLightingMatchesTheAnalyticCosine) {
    // Orthographic view of a tilted plane: N.V is the same everywhere.
    const Camera cam = viewCamera(16, 12, false);
    const ScenePlane plane{{0, 0, 0}, normalize(Vec3{0.3, -0.2, 1.0})};
    const double cosine = -dot(facing(cam, plane), normalize(cam.forward));
    const double ambient = 0.3, luminance = 1.5;
    const double want = 0.5 * luminance * (ambient + (1 - ambient) * cosine);
    auto img = depthImage(cam, [&](int x, int y) { return x == 5 && y == 5 ? double(kInf) : planeDepth(cam, plane, x, y); },
                          {"R", "G", "B"});
    const Inputs lit{{"lighting", {Value(true)}}, {"ambient", {Value(ambient)}}, {"luminance", {Value(luminance)}},
                     {"strength", {Value(0.0)}}};
    const BufferPtr out = runPass("IBS", img, lit);
    for (std::size_t i = 0; i < out->pixelCount(); ++i)
        EXPECT_NEAR(out->hostFloat("G")[i], i == 5 * 16 + 5 ? 0.5 : want, 1e-4) << i;
    // Captured normals give the same light.
    auto withN = depthImage(cam, [&](int x, int y) { return planeDepth(cam, plane, x, y); }, {"R", "G", "B", "N.x", "N.y", "N.z"});
    const Vec3 n = facing(cam, plane);
    std::fill_n(withN->writeFloat("N.x"), withN->pixelCount(), float(n.x));
    std::fill_n(withN->writeFloat("N.y"), withN->pixelCount(), float(n.y));
    std::fill_n(withN->writeFloat("N.z"), withN->pixelCount(), float(n.z));
    const BufferPtr out2 = runPass("IBS", withN, lit);
    for (std::size_t i = 0; i < out2->pixelCount(); ++i) EXPECT_NEAR(out2->hostFloat("B")[i], want, 1e-5) << i;
}

// Without a camera, lighting uses the image-space camera (docs/cameras.md).
TEST(Ibs, LightingWithoutCameraUsesTheImageSpaceCamera) {
    auto img = makeImage(4, 4, {"Z", "R", "G", "B"}, [](int, int, int) { return 3.0f; });
    EXPECT_NO_THROW(runPass("IBS", img, {{"lighting", {Value(true)}}}));
    EXPECT_NO_THROW(runPass("IBS", img)) << "silhouettes alone need no camera";
}

TEST(Ibs, StressInputsStayFiniteAndInRange) {
    const Camera cam = viewCamera(12, 9, true);
    const BufferPtr holes = depthImage(cam, [](int x, int y) {
        if (x == 3 && y == 3) return double(kNaN);
        if (x == 5 && y == 2) return -double(kInf);
        if (x == 8) return double(kInf);
        return 3.0 + 0.5 * ((x * 7 + y * 3) % 5);
    }, {"R", "G", "B", "A"});
    const BufferPtr bg = depthImage(cam, [](int, int) { return double(kInf); }, {"R", "G", "B", "A"});
    const BufferPtr one = depthImage(viewCamera(1, 1, false), [](int, int) { return 2.0; }, {"R", "G", "B", "A"});
    for (const BufferPtr& img : {holes, bg, one})
        for (const double width : {0.0, 1.0, 32.0})
            for (const bool lighting : {false, true}) {
                const BufferPtr out = runPass("IBS", img, {{"width", {Value(width)}}, {"lighting", {Value(lighting)}}});
                expectInRange(*out);
                if (width == 0.0) {
                    for (std::size_t i = 0; i < img->pixelCount(); ++i) EXPECT_EQ(out->hostFloat("Silhouette")[i], 0.0f);
                }
            }
    // NaN and -inf are no data: never outlined.
    const BufferPtr out = runPass("IBS", holes);
    EXPECT_EQ(at(out, "Silhouette", 3, 3), 0.0f);
    EXPECT_EQ(at(out, "Silhouette", 5, 2), 0.0f);
    EXPECT_EQ(at(out, "Silhouette", 7, 0), 1.0f) << "next to the background column";
}

TEST(Ibs, ResultDoesNotDependOnTheThreadCount) {
    const Camera cam = viewCamera(97, 61, true);
    const BufferPtr img = depthImage(cam, [](int x, int y) { return 3.0 + ((x / 9 + y / 7) % 3); }, {"R", "G", "B", "A"});
    const Inputs p{{"width", {Value(2.5)}}, {"lighting", {Value(true)}}};
    EXPECT_TRUE(identical(*runPass("IBS", img, p, 1), *runPass("IBS", img, p, 4)));
}

// Silhouettes and shading run vectors of pixels with the best SIMD
// instructions of the CPU: every instruction set gives the same bits (width
// 1 and a disk, both sides, lighting from reconstructed and captured normals).
TEST(Ibs, ResultDoesNotDependOnTheSimdInstructionSet) {
    const Camera cam = viewCamera(71, 45, true);
    auto img = depthImage(cam, [](int x, int y) {
        if ((x * 5 + y * 3) % 41 == 0) return double(kInf);
        if ((x + y) % 53 == 0) return double(kNaN);
        return 3.0 + ((x / 9 + y / 7) % 3) + 0.01 * x;
    }, {"R", "G", "B", "A"});
    float* a = img->writeFloat("A");
    for (std::size_t i = 0; i < img->pixelCount(); i += 7) a[i] = float(i % 5) * 0.25f;
    auto captured = depthImage(cam, [&](int x, int y) { return double(img->hostFloat("Z")[std::size_t(y) * cam.width + x]); },
                               {"R", "G", "B", "N.x", "N.y", "N.z"});
    for (std::size_t i = 0; i < captured->pixelCount(); ++i) {
        captured->writeFloat("N.x")[i] = 0.6f * std::sin(float(i));
        captured->writeFloat("N.y")[i] = 0.8f * std::cos(float(i));
        captured->writeFloat("N.z")[i] = 0.1f;
    }
    const BufferPtr images[2] = {img, captured};
    for (const BufferPtr& in : images)
        for (const Inputs& p : {Inputs{}, Inputs{{"width", {Value(2.5)}}, {"side", {Value("far")}}},
                                Inputs{{"lighting", {Value(true)}}, {"strength", {Value(0.6)}}}}) {
            const auto results = resultsPerSimdTarget([&] { return runPass("IBS", in, p); });
            for (const auto& [target, out] : results)
                EXPECT_TRUE(identical(*out, *results.front().second)) << target << " differs from " << results.front().first;
        }
}

}  // namespace
