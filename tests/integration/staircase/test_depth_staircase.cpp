// A depth staircase (treads facing the camera, steps every 8 pixels) through
// the depth-based passes, with answers known from the geometry: Normals are
// exact on every tread including the pixels beside each step, IBS outlines
// exactly the near side of each step, SSDD darkens only the far side of each
// step and nothing farther than its kernel.
#include "../../../plugins/normals/tests/depth_scenes.h"

#include <gtest/gtest.h>

using namespace darkroom;
using namespace darkroom::test;

namespace {

constexpr int kW = 40, kH = 12, kTread = 8;

Camera topDown() {
    Camera c;
    c.width = kW;
    c.height = kH;
    c.position = {0, 0, 10};
    c.forward = {0, 0, -1};
    c.up = {0, 1, 0};
    c.projection = Camera::Projection::Orthographic;
    c.viewHeight = 3.0;
    return c;
}

double treadDepth(int x) { return 4.0 + 0.25 * (x / kTread); }

BufferPtr staircase() {
    const Camera cam = topDown();
    return depthImage(cam, [](int x, int) { return treadDepth(x); }, {"R", "G", "B", "A"});
}

float at(const BufferPtr& b, const char* c, int x, int y) { return b->hostFloat(c)[std::size_t(y) * kW + x]; }

}  // namespace

TEST(DepthStaircase, DiscontinuityAwareNormalsAreExactOnEveryTread) {
    for (const char* method : {"nearest", "extrapolated"}) {
        const BufferPtr out = runPass("Normals", staircase(), {{"method", {Value(method)}}});
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x) {
                const Vec3 n = vec(*out, "N", std::size_t(y) * kW + x);
                EXPECT_LT(angleDegrees(n, {0, 0, 1}), 1e-3) << method << " at " << x << "," << y;
            }
    }
    // The simple central difference is wrong beside each step: the test can tell.
    const BufferPtr central = runPass("Normals", staircase(), {{"method", {Value("central")}}});
    EXPECT_GT(angleDegrees(vec(*central, "N", 5 * kW + kTread), {0, 0, 1}), 10.0);
}

TEST(DepthStaircase, SilhouettesSitExactlyOnTheNearSideOfEachStep) {
    const BufferPtr out = runPass("IBS", staircase(), {{"width", {Value(1.0)}}, {"side", {Value("near")}}});
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const bool nearSide = (x + 1) % kTread == 0 && x + 1 < kW;  // 7, 15, 23, 31
            EXPECT_EQ(at(out, "Silhouette", x, y), nearSide ? 1.0f : 0.0f) << x << "," << y;
        }
}

TEST(DepthStaircase, DepthDarkeningOnlyOnTheFarSideOfEachStep) {
    const BufferPtr out = runPass("SSDD", staircase(),
                                  {{"sigma", {Value(1.0)}}, {"sigmaUnits", {Value("pixels")}}, {"strength", {Value(1.0)}}});
    const int y = kH / 2;
    for (int step = kTread; step < kW; step += kTread) {
        EXPECT_LT(at(out, "SSDD", step, y), 1.0f) << "far side of the step at " << step;
        EXPECT_EQ(at(out, "SSDD", step - 1, y), 1.0f) << "near side of the step at " << step;
        for (int x = step; x + 1 < step + kTread; ++x)
            EXPECT_LE(at(out, "SSDD", x, y), at(out, "SSDD", x + 1, y)) << "darkening fades with distance, x=" << x;
        // Beyond the 3-sigma kernel nothing is darkened.
        EXPECT_EQ(at(out, "SSDD", step + 4, y), 1.0f) << step;
    }
    for (int x = 0; x < kTread; ++x) EXPECT_EQ(at(out, "SSDD", x, y), 1.0f) << "nearest tread, x=" << x;
    for (std::size_t i = 0; i < out->pixelCount(); ++i) {
        const float f = out->hostFloat("SSDD")[i];
        ASSERT_TRUE(f >= 0.0f && f <= 1.0f) << i;
    }
}
