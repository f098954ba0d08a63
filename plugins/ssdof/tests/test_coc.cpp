// The thin-lens circle of confusion against the geometry it models.
#include "../src/coc.h"

#include <darkroom/error.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace darkroom;
using namespace darkroom::ssdof;

namespace {

Camera camera(int h, double fov) {
    Camera c;
    c.width = h;
    c.height = h;
    c.fovYDegrees = fov;
    return c;
}

// Diameter of the cone from a point at depth z through a lens of diameter A,
// cut by the focal plane at zf (similar triangles), in pixels of that plane,
// halved: the radius the image shows.
double expectedRadius(const Camera& cam, double A, double zf, double z) {
    return A * std::fabs(z - zf) / z / cam.pixelSizeAt(zf) / 2.0;
}

}  // namespace

TEST(CircleOfConfusion, MatchesTheThinLensConeCutByTheFocalPlane) {
    const Camera cam = camera(480, 40.0);
    const LensModel lens = makeLens(cam, 480, 0.08, 3.0, 1000.0);
    for (double z : {0.5, 1.0, 2.0, 2.9, 3.0, 3.1, 5.0, 40.0}) {
        const double want = expectedRadius(cam, 0.08, 3.0, z);
        EXPECT_NEAR(std::fabs(lens.signedRadius(float(z))), want, 1e-4 * want + 1e-5) << z;
        EXPECT_EQ(lens.signedRadius(float(z)) < 0, z < 3.0) << "near field is negative, z = " << z;
    }
    EXPECT_EQ(lens.signedRadius(3.0f), 0.0f);
}

TEST(CircleOfConfusion, BackgroundTakesTheFiniteFarFieldLimit) {
    const Camera cam = camera(256, 30.0);
    const LensModel lens = makeLens(cam, 256, 0.1, 2.0, 1000.0);
    // A |z - zf| / z -> A as z -> inf.
    const double limit = 0.1 / cam.pixelSizeAt(2.0) / 2.0;
    const float inf = std::numeric_limits<float>::infinity();
    EXPECT_NEAR(lens.signedRadius(inf), limit, 1e-4 * limit);
    EXPECT_NEAR(lens.signedRadius(1e30f), limit, 1e-4 * limit);
    EXPECT_EQ(lens.signedRadius(std::nanf("")), lens.signedRadius(inf)) << "no data is background";
}

TEST(CircleOfConfusion, IsClampedByMaxBlurAndVanishesWithoutAperture) {
    const Camera cam = camera(100, 60.0);
    EXPECT_EQ(makeLens(cam, 100, 5.0, 1.0, 7.0).signedRadius(100.0f), 7.0f);
    EXPECT_EQ(makeLens(cam, 100, 5.0, 1.0, 7.0).signedRadius(0.01f), -7.0f);
    EXPECT_EQ(makeLens(cam, 100, 5.0, 1.0, 7.0).signedRadius(0.0f), 7.0f) << "z <= 0 is no surface";
    EXPECT_EQ(makeLens(cam, 100, 0.0, 1.0, 7.0).signedRadius(3.0f), 0.0f);
}

TEST(CircleOfConfusion, FocusAtInfinityBlursOnlyTheNearField) {
    const Camera cam = camera(100, 60.0);
    const LensModel lens = makeLens(cam, 100, 0.01, std::numeric_limits<double>::infinity(), 1000.0);
    EXPECT_EQ(lens.signedRadius(std::numeric_limits<float>::infinity()), 0.0f);
    // zf -> inf: radius A / (2 h z), h the pixel size at unit depth.
    EXPECT_NEAR(lens.signedRadius(2.0f), -0.01 / (2.0 * cam.pixelSizeAt(1.0) * 2.0), 1e-5);
}

TEST(CircleOfConfusion, AutoFocusTakesTheMedianOfTheCentre) {
    std::vector<float> z(9 * 7, 10.0f);
    const float inf = std::numeric_limits<float>::infinity();
    // 5x5 window around (4, 3): 24 pixels at 10, one at 2 -> median 10.
    z[3 * 9 + 4] = 2.0f;
    EXPECT_EQ(autoFocusDistance(z.data(), 9, 7), 10.0);
    for (float& d : z) d = inf;
    EXPECT_EQ(autoFocusDistance(z.data(), 9, 7), std::numeric_limits<double>::infinity());
    z[3 * 9 + 4] = 4.0f;  // only finite pixel
    EXPECT_EQ(autoFocusDistance(z.data(), 9, 7), 4.0);
}

TEST(CircleOfConfusion, RefusesAnImageWithoutRows) {
    EXPECT_THROW(makeLens(camera(10, 30.0), 0, 0.1, 1.0, 8.0), Error);
}
