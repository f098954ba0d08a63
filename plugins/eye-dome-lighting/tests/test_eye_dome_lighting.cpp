// EyeDomeLighting against exact answers: a plane facing the camera is flat
// (EDL = 1, colour untouched), a tilted plane gives the closed-form response
// of its log depth, a depth step darkens exactly the far side by the
// predicted amount, background never shades, scales combine as stated.
#include "../../normals/tests/depth_scenes.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace darkroom;
using namespace darkroom::test;

namespace {

const float kInf = std::numeric_limits<float>::infinity();

float at(const BufferPtr& b, const char* c, int x, int y) { return b->hostFloat(c)[std::size_t(y) * b->width() + x]; }

// The ring of 8 offsets for radius 1 (angles 2πk/8, rounded).
const int kRing1[8][2] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};

}  // namespace

TEST(EyeDomeLighting, PlaneFacingTheCameraIsFlat) {
    for (const bool perspective : {true, false}) {
        Camera cam = viewCamera(40, 30, perspective);
        cam.forward = {0, 0, -1};
        const ScenePlane plane{{0, 0, 0}, {0, 0, 1}};
        const auto img = depthImage(cam, [&](int x, int y) { return planeDepth(cam, plane, x, y); }, {"R", "G", "B"});
        const BufferPtr out = runPass("EyeDomeLighting", img, {{"scales", {Value(3)}}, {"strength", {Value(5.0)}}});
        for (std::size_t i = 0; i < out->pixelCount(); ++i) {
            ASSERT_EQ(out->hostFloat("EDL")[i], 1.0f) << i;
            ASSERT_EQ(out->hostFloat("R")[i], 0.5f);
        }
    }
}

TEST(EyeDomeLighting, TiltedPlaneGivesTheClosedFormResponse) {
    // Orthographic, depth linear in x: Z = a + b (x + 0.5) for every row.
    Camera cam = viewCamera(48, 20, false);
    cam.forward = {0, 0, -1};
    const double a = 4.0, b = 0.02;
    const auto img = depthImage(cam, [&](int x, int) { return a + b * (x + 0.5); });
    const double strength = 0.2;
    const BufferPtr out = runPass("EyeDomeLighting", img, {{"scales", {Value(1)}}, {"strength", {Value(strength)}}});
    for (int y = 1; y < 19; ++y)
        for (int x = 1; x < 47; ++x) {
            const double zp = a + b * (x + 0.5);
            double response = 0;
            for (const auto& o : kRing1) response += std::max(0.0, std::log2(zp) - std::log2(a + b * (x + o[0] + 0.5)));
            const double want = std::exp(-300.0 * strength * response / 8.0);
            ASSERT_NEAR(at(out, "EDL", x, y), want, 2e-5) << x << "," << y;
        }
    // Smooth: no pixel differs from its neighbour by more than the slope of 1/Z allows.
    for (int x = 2; x < 46; ++x) EXPECT_LT(std::fabs(at(out, "EDL", x + 1, 5) - at(out, "EDL", x, 5)), 2e-3);
}

TEST(EyeDomeLighting, DepthStepShadesExactlyTheFarSide) {
    const Camera cam = viewCamera(20, 12, true);
    const int split = 9;
    const auto img = depthImage(cam, [&](int x, int) { return x < split ? 4.0 : 6.0; }, {"R", "G", "B"});
    const double strength = 0.01;
    const BufferPtr out = runPass("EyeDomeLighting", img, {{"scales", {Value(1)}}, {"strength", {Value(strength)}}});
    // Far pixels next to the step see three nearer neighbours (dx = -1).
    const double want = std::exp(-300.0 * strength * 3.0 * std::log2(6.0 / 4.0) / 8.0);
    for (int y = 1; y < 11; ++y) {
        for (int x = 0; x < 20; ++x) {
            const float e = at(out, "EDL", x, y);
            if (x == split) {
                EXPECT_NEAR(e, want, 1e-5);
                EXPECT_NEAR(at(out, "R", x, y), 0.5 * want, 1e-5);
            } else {
                EXPECT_EQ(e, 1.0f) << x;  // the near side and the far interior are untouched
            }
        }
    }
    // Two scales, weights 2/3 and 1/3. The radius-2 ring is (±2, 0), (0, ±2)
    // and the four diagonals (±1, ±1): from the step's far column three of them
    // are nearer, from the next column only (-2, 0).
    const BufferPtr two = runPass("EyeDomeLighting", img, {{"scales", {Value(2)}}, {"strength", {Value(strength)}}});
    const double one = std::exp(-300.0 * strength * 1.0 * std::log2(6.0 / 4.0) / 8.0);
    EXPECT_NEAR(at(two, "EDL", split, 5), 2.0 / 3.0 * want + 1.0 / 3.0 * want, 1e-5);
    EXPECT_NEAR(at(two, "EDL", split + 1, 5), 2.0 / 3.0 + 1.0 / 3.0 * one, 1e-5);
}

TEST(EyeDomeLighting, BackgroundNeverShadesAndStaysOne) {
    const Camera cam = viewCamera(10, 6, true);
    const auto img = depthImage(cam, [&](int x, int) { return x < 5 ? 3.0 : double(kInf); }, {"R", "G", "B"});
    img->writeFloat("R")[7] = 0.25f;
    const BufferPtr out = runPass("EyeDomeLighting", img, {{"strength", {Value(3.0)}}});
    for (std::size_t i = 0; i < out->pixelCount(); ++i) ASSERT_EQ(out->hostFloat("EDL")[i], 1.0f) << i;
    EXPECT_EQ(out->hostFloat("R")[7], 0.25f);
}

TEST(EyeDomeLighting, ResultDoesNotDependOnThreadCount) {
    const Camera cam = viewCamera(64, 48, true);
    const auto img = depthImage(cam, [&](int x, int y) { return 3.0 + 0.3 * std::sin(0.3 * x) * std::cos(0.2 * y) + (x > 30 ? 1.0 : 0.0); });
    const BufferPtr one = runPass("EyeDomeLighting", img, {{"scales", {Value(3)}}}, 1);
    const BufferPtr four = runPass("EyeDomeLighting", img, {{"scales", {Value(3)}}}, 4);
    EXPECT_TRUE(identical(*one, *four));
}
