// SSDD: planes are not darkened, a step darkens only its far side with a
// monotone decay, background never contributes, stress inputs stay in range.
#include "../../normals/tests/depth_scenes.h"

#include <darkroom/error.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

using namespace darkroom;
using namespace darkroom::test;

namespace {

const float kInf = std::numeric_limits<float>::infinity();
const float kNaN = std::numeric_limits<float>::quiet_NaN();

Inputs pixels(double sigma, double strength = 1.0) {
    return {{"sigma", {Value(sigma)}}, {"sigmaUnits", {Value("pixels")}}, {"strength", {Value(strength)}}};
}

void expectInRange(const Buffer& b) {
    const float* f = b.hostFloat("SSDD");
    ASSERT_NE(f, nullptr);
    for (std::size_t i = 0; i < b.pixelCount(); ++i) {
        ASSERT_TRUE(std::isfinite(f[i])) << i;
        ASSERT_GE(f[i], 0.0f) << i;
        ASSERT_LE(f[i], 1.0f) << i;
    }
}

TEST(Ssdd, TiltedPlaneIsNotDarkenedAwayFromTheBorder) {
    const ScenePlane plane{{0, 0, 0}, normalize(Vec3{0.3, -0.2, 1.0})};
    for (const bool perspective : {true, false}) {
        const Camera cam = viewCamera(64, 48, perspective);
        const BufferPtr out = runPass("SSDD", depthImage(cam, [&](int x, int y) { return planeDepth(cam, plane, x, y); }),
                                      pixels(3.0, 5.0));
        expectInRange(*out);
        // The kernel reaches 9 pixels: beyond that from the border the blur of
        // a plane is the plane (orthographic: Z is affine in the image) or
        // lies behind it (perspective: Z = 1/affine is convex).
        for (int y = 10; y < cam.height - 10; ++y)
            for (int x = 10; x < cam.width - 10; ++x)
                EXPECT_NEAR(out->hostFloat("SSDD")[std::size_t(y) * cam.width + x], 1.0f, 1e-4f)
                    << (perspective ? "perspective " : "orthographic ") << x << "," << y;
    }
}

// Near surface (Z = 4) left of column `split`, far surface (Z = 6) right of it.
BufferPtr step(int w, int h, int split, bool perspective = true) {
    return depthImage(viewCamera(w, h, perspective), [split](int x, int) { return x < split ? 4.0 : 6.0; }, {"R", "G", "B", "A"});
}

TEST(Ssdd, StepDarkensOnlyItsFarSideDecayingWithDistance) {
    for (const bool perspective : {true, false}) {
        const int w = 60, h = 10, split = 30;
        const double sigma = 3.0;
        const BufferPtr out = runPass("SSDD", step(w, h, split, perspective), pixels(sigma));
        expectInRange(*out);
        const float* f = out->hostFloat("SSDD");
        for (int y = 0; y < h; ++y) {
            const float* row = f + std::size_t(y) * w;
            for (int x = 0; x < split; ++x) EXPECT_EQ(row[x], 1.0f) << "near side " << x;
            EXPECT_LT(row[split], 0.9f) << "the far pixel next to the step is darkened";
            for (int x = split + 1; x < w; ++x) EXPECT_GE(row[x], row[x - 1]) << "monotone at " << x;
            for (int x = split + int(3 * sigma) + 1; x < w; ++x) EXPECT_NEAR(row[x], 1.0f, 1e-5f) << "beyond the kernel " << x;
            // Rows agree (up to the rounding of differently normalised
            // vertical sums): the step does not depend on y.
            for (int x = 0; x < w; ++x) EXPECT_NEAR(row[x], f[x], 1e-6f);
        }
    }
}

TEST(Ssdd, StrongerAndWiderDarkensMore) {
    const BufferPtr img = step(60, 4, 30);
    const float base = runPass("SSDD", img, pixels(3.0, 1.0))->hostFloat("SSDD")[31];
    EXPECT_LT(runPass("SSDD", img, pixels(3.0, 2.0))->hostFloat("SSDD")[31], base);
    EXPECT_LT(runPass("SSDD", img, pixels(3.0, 1.0))->hostFloat("SSDD")[36],
              runPass("SSDD", img, pixels(1.0, 1.0))->hostFloat("SSDD")[36] + 1e-7f);
}

TEST(Ssdd, SigmaAsAFractionOfTheImageHeightEqualsPixels) {
    const BufferPtr img = step(60, 20, 30);
    const BufferPtr a = runPass("SSDD", img, pixels(2.0));
    const BufferPtr b = runPass("SSDD", img, {{"sigma", {Value(0.1)}}, {"sigmaUnits", {Value("imageHeight")}}, {"strength", {Value(1.0)}}});
    EXPECT_TRUE(identical(*a, *b));
}

TEST(Ssdd, BackgroundNeverContributes) {
    // Background on the left, a far plane on the right: no occluder, no darkening.
    const Camera cam = viewCamera(40, 8, true);
    const BufferPtr out = runPass("SSDD", depthImage(cam, [](int x, int) { return x < 20 ? double(kInf) : 6.0; }), pixels(4.0));
    for (std::size_t i = 0; i < out->pixelCount(); ++i) EXPECT_NEAR(out->hostFloat("SSDD")[i], 1.0f, 1e-6f) << i;
}

TEST(Ssdd, ApplyMultipliesColourAndKeepsAlphaAndOtherChannels) {
    const BufferPtr img = step(60, 4, 30);
    const BufferPtr out = runPass("SSDD", img, [] { auto p = pixels(3.0); p["apply"] = {Value(true)}; return p; }());
    const BufferPtr plain = runPass("SSDD", img, pixels(3.0));
    for (std::size_t i = 0; i < out->pixelCount(); ++i) {
        const float f = out->hostFloat("SSDD")[i];
        EXPECT_FLOAT_EQ(out->hostFloat("R")[i], 0.5f * f);
        EXPECT_FLOAT_EQ(out->hostFloat("B")[i], 0.5f * f);
        EXPECT_EQ(out->hostFloat("A")[i], 0.5f);
        EXPECT_EQ(plain->hostFloat("R")[i], 0.5f);
        EXPECT_EQ(out->hostFloat("Z")[i], img->hostFloat("Z")[i]);
    }
    EXPECT_EQ(out->metadata(), img->metadata());
}

TEST(Ssdd, StressInputsStayFiniteAndInRange) {
    const Camera cam = viewCamera(12, 9, true);
    const BufferPtr holes = depthImage(cam, [](int x, int y) {
        if (x == 3 && y == 3) return double(kNaN);
        if (x == 5 && y == 2) return -double(kInf);
        if (x == 8) return double(kInf);
        return 3.0 + 0.5 * ((x * 7 + y * 3) % 5);
    });
    const BufferPtr bg = depthImage(cam, [](int, int) { return double(kInf); });
    const BufferPtr one = depthImage(viewCamera(1, 1, false), [](int, int) { return 2.0; });
    for (const BufferPtr& img : {holes, bg, one})
        for (const Inputs& p : {pixels(0.0), pixels(0.05), pixels(2.0, 100.0), pixels(512.0, 100.0),
                                Inputs{{"sigma", {Value(512.0)}}}}) {
            const BufferPtr out = runPass("SSDD", img, p);
            expectInRange(*out);
            for (std::size_t i = 0; i < img->pixelCount(); ++i)
                if (!std::isfinite(img->hostFloat("Z")[i])) {
                    EXPECT_EQ(out->hostFloat("SSDD")[i], 1.0f);
                }
        }
    // Zero sigma: no blur, no darkening.
    for (std::size_t i = 0; i < holes->pixelCount(); ++i)
        EXPECT_EQ(runPass("SSDD", holes, pixels(0.0))->hostFloat("SSDD")[i], 1.0f);
}

// Without a camera: image space (docs/cameras.md); flat depth, no darkening.
TEST(Ssdd, WithoutCameraFlatDepthIsNotDarkened) {
    auto img = makeImage(4, 4, {"Z"}, [](int, int, int) { return 3.0f; });
    const BufferPtr out = runPass("SSDD", img);
    const float* f = out->requireFloat("SSDD");
    for (std::size_t i = 0; i < out->pixelCount(); ++i) EXPECT_NEAR(f[i], 1.0f, 1e-6f) << i;
}

TEST(Ssdd, ResultDoesNotDependOnTheThreadCount) {
    const Camera cam = viewCamera(97, 61, true);
    const BufferPtr img = depthImage(cam, [](int x, int y) { return 3.0 + ((x / 9 + y / 7) % 3); }, {"R", "G", "B"});
    EXPECT_TRUE(identical(*runPass("SSDD", img, pixels(4.0), 1), *runPass("SSDD", img, pixels(4.0), 4)));
}

}  // namespace
