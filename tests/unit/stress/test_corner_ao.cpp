// cornerAo against its closed form at a few k, and against a numeric
// quadrature of the hemisphere integral for both weightings.
#include <darkroom/error.h>
#include <darkroom/accuracy/stress_scenes.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace darkroom;
using reference::AoWeighting;

namespace {

constexpr double kPi = 3.14159265358979323846;

// AO of a point on the floor y = 0 at distance d from the wall z = d (which
// rises over y >= 0): the mean visibility over the upper hemisphere,
// cosine- or uniformly weighted, by the midpoint rule in (theta, phi).
double quadrature(double d, double radius, AoWeighting w) {
    const int nt = 600, np = 1200;
    double visible = 0, total = 0;
    for (int i = 0; i < nt; ++i) {
        const double theta = (i + 0.5) * (kPi / 2) / nt;  // from the normal
        const double weight = std::sin(theta) * (w == AoWeighting::Cosine ? std::cos(theta) : 1.0);
        for (int j = 0; j < np; ++j) {
            const double phi = (j + 0.5) * 2 * kPi / np;
            const double dz = std::sin(theta) * std::cos(phi);
            // The ray along (., cos theta, dz) meets the wall at t = d / dz.
            const bool blocked = dz > 0 && d / dz < radius;
            total += weight;
            if (!blocked) visible += weight;
        }
    }
    return visible / total;
}

TEST(CornerAo, ClosedFormAtKnownPoints) {
    // k = 0 (on the joint): half the hemisphere is wall, either weighting.
    EXPECT_NEAR(stress::cornerAo(0.0, 1.0, AoWeighting::Cosine), 0.5, 1e-12);
    EXPECT_NEAR(stress::cornerAo(0.0, 1.0, AoWeighting::Uniform), 0.5, 1e-12);
    // k = 1 and beyond: the wall is out of reach.
    EXPECT_DOUBLE_EQ(stress::cornerAo(2.0, 2.0, AoWeighting::Cosine), 1.0);
    EXPECT_DOUBLE_EQ(stress::cornerAo(5.0, 2.0, AoWeighting::Uniform), 1.0);
    // k = 1/2: cosine 1 - (pi/3 - sqrt(3)/4) / pi, uniform 3/4.
    EXPECT_NEAR(stress::cornerAo(0.5, 1.0, AoWeighting::Cosine), 1.0 - (kPi / 3 - std::sqrt(3.0) / 4) / kPi, 1e-12);
    EXPECT_NEAR(stress::cornerAo(1.0, 2.0, AoWeighting::Uniform), 0.75, 1e-12);
    // Only d / R matters; a negative distance counts as its magnitude.
    EXPECT_DOUBLE_EQ(stress::cornerAo(0.3, 1.0, AoWeighting::Cosine), stress::cornerAo(3.0, 10.0, AoWeighting::Cosine));
    EXPECT_DOUBLE_EQ(stress::cornerAo(-0.3, 1.0, AoWeighting::Uniform), stress::cornerAo(0.3, 1.0, AoWeighting::Uniform));
}

TEST(CornerAo, MatchesTheHemisphereIntegral) {
    for (double k : {0.0, 0.1, 0.3, 0.5, 0.8, 0.95, 1.2})
        for (AoWeighting w : {AoWeighting::Cosine, AoWeighting::Uniform}) {
            const double R = 0.7;
            EXPECT_NEAR(stress::cornerAo(k * R, R, w), quadrature(k * R, R, w), 2e-3)
                << "k = " << k << (w == AoWeighting::Cosine ? ", cosine" : ", uniform");
        }
}

TEST(CornerAo, IncreasesWithDistanceAndCosineIsDarkerNearTheJoint) {
    double previous = 0;
    for (double d = 0; d <= 1.0; d += 0.05) {
        const double c = stress::cornerAo(d, 1.0, AoWeighting::Cosine);
        EXPECT_GE(c, previous);
        previous = c;
        // Near the joint the wall sits at grazing directions, which the cosine
        // weighting counts less: cosine AO >= uniform AO.
        EXPECT_GE(c + 1e-12, stress::cornerAo(d, 1.0, AoWeighting::Uniform));
    }
}

TEST(CornerAo, RejectsANonPositiveRadius) {
    EXPECT_THROW(stress::cornerAo(0.5, 0.0, AoWeighting::Cosine), Error);
    EXPECT_THROW(stress::cornerAo(0.5, -1.0, AoWeighting::Uniform), Error);
}

// The corner scene's analytic AO uses the distance to the other plane.
TEST(CornerAo, CornerSceneAnalyticAoUsesTheOtherPlane) {
    const auto s = stress::make("corner", 0);
    ASSERT_TRUE(s.analyticAo);
    const double R = s.aoRadius;
    EXPECT_NEAR(s.analyticAo({0.3, 0.0, 0.25 * R}, R, AoWeighting::Cosine),
                stress::cornerAo(0.25 * R, R, AoWeighting::Cosine), 1e-12);  // floor point
    EXPECT_NEAR(s.analyticAo({-2.0, 0.6 * R, 0.0}, R, AoWeighting::Uniform),
                stress::cornerAo(0.6 * R, R, AoWeighting::Uniform), 1e-12);  // wall point
    EXPECT_DOUBLE_EQ(s.analyticAo({0.0, 0.0, 3.0 * R}, R, AoWeighting::Cosine), 1.0);
}

}  // namespace
