// The closed forms against direct numerical integration of their definition:
// (1/pi) * integral over the hemisphere of [a ray in direction w hits the
// primitive nearer than R] * (w . n)+ dw, with the ray test written out here
// (ray-sphere and ray-cylinder intersection), independent of the code tested.
#include "../src/closed_forms.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

using namespace darkroom;
using namespace darkroom::listao;

namespace {

constexpr double kPi = 3.14159265358979323846;

struct D3 {
    double x, y, z;
};
D3 operator-(D3 a, D3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
D3 operator*(D3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dot(D3 a, D3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3f f(D3 a) { return {float(a.x), float(a.y), float(a.z)}; }

// Cosine-weighted hemisphere integral around n = +z by the midpoint rule in
// (cos^2 of the polar angle, azimuth): that substitution makes the cosine
// weight uniform, so each cell carries the same weight.
double hemisphere(const std::function<bool(D3)>& occluded, int rings = 1500, int sectors = 1500) {
    double hits = 0;
    for (int i = 0; i < rings; ++i) {
        const double c2 = (i + 0.5) / rings, c = std::sqrt(c2), s = std::sqrt(1 - c2);
        for (int j = 0; j < sectors; ++j) {
            const double phi = 2 * kPi * (j + 0.5) / sectors;
            hits += occluded({s * std::cos(phi), s * std::sin(phi), c});
        }
    }
    return hits / (double(rings) * sectors);
}

// Nearest positive distance along unit w from the origin to sphere (c, r).
double raySphere(D3 w, D3 c, double r) {
    const double b = dot(w, c), k = dot(c, c) - r * r, disc = b * b - k;
    if (disc < 0) return INFINITY;
    const double t = b - std::sqrt(disc);
    return t > 0 ? t : INFINITY;
}

// Nearest positive distance along unit w from the origin to the infinite
// cylinder with axis through point a along unit t, radius r.
double rayCylinder(D3 w, D3 a, D3 t, double r) {
    const D3 wp = w - t * dot(w, t), ap = (D3{0, 0, 0} - a) - t * dot(D3{0, 0, 0} - a, t);
    const double qa = dot(wp, wp), qb = 2 * dot(wp, ap), qc = dot(ap, ap) - r * r;
    const double disc = qb * qb - 4 * qa * qc;
    if (qa <= 0 || disc < 0) return INFINITY;
    const double t0 = (-qb - std::sqrt(disc)) / (2 * qa);
    return t0 > 0 ? t0 : INFINITY;
}

}  // namespace

TEST(ClosedForms, CapAboveTheHorizonIsSinSquaredTimesCos) {
    EXPECT_FLOAT_EQ(capOcclusion(1.0f, 0.25f), 0.25f);
    EXPECT_FLOAT_EQ(capOcclusion(0.8f, 0.36f), 0.8f * 0.36f);
    EXPECT_FLOAT_EQ(capOcclusion(-0.9f, 0.1f), 0.0f);  // wholly below
    EXPECT_FLOAT_EQ(capOcclusion(0.5f, 0.0f), 0.0f);
    // A half-space (sigma = 90 degrees) tilted by theta covers (1 + cos theta) / 2.
    for (float c : {-0.7f, 0.0f, 0.3f}) EXPECT_NEAR(capOcclusion(c, 1.0f), 0.5f * (1 + c), 1e-5f) << c;
}

TEST(ClosedForms, SpheresAgainstIntegrationIncludingHorizonAndRadiusClipping) {
    struct Case {
        D3 centre;
        double r, R;
    };
    // Above the horizon; straddling it (centre below, at, above); cut by R
    // (the silhouette's rim beyond R, the near side within).
    const Case cases[] = {{{0.2, 0.1, 1.0}, 0.4, 10}, {{1.0, 0.0, 0.3}, 0.6, 10},  {{1.0, 0.2, 0.0}, 0.5, 10},
                          {{1.0, 0.0, -0.2}, 0.5, 10}, {{0.3, 0.2, 0.9}, 0.5, 0.8}, {{1.0, 0.0, 0.1}, 0.7, 0.9}};
    for (const Case& k : cases) {
        const double want = hemisphere([&](D3 w) { return raySphere(w, k.centre, k.r) < k.R; });
        const float got = sphereOcclusion({0, 0, 0}, {0, 0, 1}, f(k.centre), float(k.r), float(k.R));
        EXPECT_NEAR(got, want, 2e-3) << k.centre.x << " " << k.centre.y << " " << k.centre.z << " r " << k.r << " R " << k.R;
    }
    // Beyond R, and the receiver on its own sphere.
    EXPECT_EQ(sphereOcclusion({0, 0, 0}, {0, 0, 1}, {0, 0, 2}, 0.5f, 1.4f), 0.0f);
    EXPECT_EQ(sphereOcclusion({0, 0, 0}, {0, 0, 1}, {0, 0, -0.5f}, 0.5f, 1.0f), 0.0f);
}

TEST(ClosedForms, AThinLineAgainstIntegration) {
    // A straight line of radius r at height h above the receiver, along x,
    // long enough that R cuts it: the thin-line integral against ray
    // casting the cylinder.
    for (const double h : {0.3, 0.6}) {
        for (const double tilt : {0.0, 0.5}) {  // the line's height offset in y: partly to one side
            const double r = 0.01, R = 1.0;
            const D3 a{-3, tilt, h}, t{1, 0, 0};
            const double want = hemisphere([&](D3 w) { return rayCylinder(w, a, t, r) < R; }, 3000, 3000);
            const float got = tubeOcclusion({0, 0, 0}, {0, 0, 1}, f(a), {3, float(tilt), float(h)}, float(r), float(r), float(R));
            EXPECT_NEAR(got, want, 0.03 * want + 2e-4) << "h " << h << " tilt " << tilt;
        }
    }
}

TEST(ClosedForms, AThickLineIsWithinItsStatedError) {
    // r / d = 0.5: the thin-line model's own limit (README: about 10 %).
    const double r = 0.25, R = 2.0, h = 0.5;
    const D3 a{-5, 0, h}, t{1, 0, 0};
    const double want = hemisphere([&](D3 w) { return rayCylinder(w, a, t, r) < R; });
    const float got = tubeOcclusion({0, 0, 0}, {0, 0, 1}, f(a), {5, 0, float(h)}, float(r), float(r), float(R));
    EXPECT_NEAR(got, want, 0.1 * want);
}

TEST(ClosedForms, ALineDoesNotOccludeItsOwnSurface) {
    // A receiver on the side of a straight line, facing away from its axis.
    EXPECT_EQ(tubeOcclusion({0, 0, 0}, {0, 0, 1}, {-1, 0, -0.1f}, {1, 0, -0.1f}, 0.1f, 0.1f, 1.0f), 0.0f);
}
