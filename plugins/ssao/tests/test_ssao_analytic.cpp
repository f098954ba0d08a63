// SSAO against known answers: an unoccluded plane (AO = 1) and the floor at
// the foot of a wall, whose cosine-weighted AO with a finite radius is
// computed here by quadrature over the hemisphere.
#include "analytic_scenes.h"

#include <darkroom/core/run_filter.h>
#include <darkroom/core/registry.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

using namespace darkroom;
using namespace ssao_test;

namespace {

constexpr double kPi = std::numbers::pi;
using Inputs = std::map<std::string, std::vector<Value>>;

BufferPtr runSsao(const BufferPtr& image, Inputs params, int threads = 2) {
    auto f = test::pluginRegistry().createFilter("SSAO");
    params["image"] = {Value(image)};
    FilterRunOptions o;
    o.threads = threads;
    return runFilter(*f, params, o).outputs.at("image").asImage();
}

// Cosine-weighted occlusion, within distance R, of a floor point at distance
// d in front of a step of height h (an infinite wall x = 0, y <= h, solid
// behind it). Midpoint rule over the polar angle theta (from the floor normal) and the
// azimuth phi (from the direction toward the wall): a ray meets the wall
// plane at t = d / (sin theta cos phi), at height t cos theta.
double stepOcclusionQuadrature(double d, double h, double R, int n = 1000) {
    double sum = 0;
    const double dt = 0.5 * kPi / n, dp = 2.0 * kPi / n;
    for (int i = 0; i < n; ++i) {
        const double th = (i + 0.5) * dt;
        const double st = std::sin(th), ct = std::cos(th);
        for (int j = 0; j < n; ++j) {
            const double cp = std::cos((j + 0.5) * dp);
            if (cp <= 0) continue;
            const double t = d / (st * cp);
            if (t <= R && t * ct <= h) sum += ct * st;
        }
    }
    return sum * dt * dp / kPi;
}

// The same for an infinite vertical wall (a step of infinite height).
double cornerOcclusionQuadrature(double d, double R, int n = 1000) {
    return stepOcclusionQuadrature(d, std::numeric_limits<double>::infinity(), R, n);
}

// The same integral in closed form, k = d / R < 1: (acos k - k sqrt(1 - k^2)) / pi;
// it tends to 1/2 at the foot of the wall (half the hemisphere, by symmetry).
double cornerOcclusionClosedForm(double k) {
    return k >= 1 ? 0.0 : (std::acos(k) - k * std::sqrt(1 - k * k)) / kPi;
}

// Continuous pixel coordinates of world point p.
void projectPoint(const Camera& c, const Vec3& p, double& px, double& py) {
    Vec3 r, u, f;
    c.basis(r, u, f);
    const Vec3 rel = p - c.position;
    const double depth = dot(rel, f);
    double sx = dot(rel, r), sy = dot(rel, u);
    if (c.projection == Camera::Projection::Perspective) sx /= depth, sy /= depth;
    const double hh = c.halfHeight(), hw = hh * c.width / c.height;
    px = (sx / hw + 1) * 0.5 * c.width;
    py = (1 - sy / hh) * 0.5 * c.height;
}

}  // namespace

TEST(SsaoReference, CornerQuadratureMatchesClosedForm) {
    // Guards the reference itself: two independent evaluations of one integral.
    for (double k : {0.0, 0.1, 0.3, 0.5, 0.8, 0.99, 1.2})
        EXPECT_NEAR(cornerOcclusionQuadrature(k, 1.0), cornerOcclusionClosedForm(k), 2e-3) << "k = " << k;
    EXPECT_NEAR(cornerOcclusionClosedForm(0.0), 0.5, 1e-12);
}

TEST(SsaoAnalytic, TiltedPlaneIsUnoccluded) {
    const Vec3 normal = normalize(Vec3{0.25, 1, 0.15});
    for (bool ortho : {false, true}) {
        Camera cam = lookAt({0.5, 5, 3.5}, {0, 0, 0}, 160, 120);
        if (ortho) {
            cam.projection = Camera::Projection::Orthographic;
            cam.viewHeight = 4;
        }
        const auto z = depthImage(cam, [&](const Vec3& o, const Vec3& d) { return planeHit(o, d, {0, 0, 0}, normal); });
        for (const char* method : {"hemisphere", "horizon"})
            for (const char* units : {"imageHeight", "world"})
                for (const char* resolution : {"full", "half"}) {
                Inputs p{{"method", {Value(method)}}, {"radiusUnits", {Value(units)}}, {"resolution", {Value(resolution)}}};
                if (std::string(units) == "world") p["radius"] = {Value(0.5)};
                const BufferPtr out = runSsao(z, p);
                const float* ao = out->hostFloat("AO");
                float worst = 0;
                std::size_t at = 0;
                for (std::size_t i = 0; i < out->pixelCount(); ++i)
                    if (std::fabs(ao[i] - 1.0f) > worst) worst = std::fabs(ao[i] - 1.0f), at = i;
                EXPECT_LE(worst, 0.02f) << method << ", " << units << ", " << resolution
                                        << (ortho ? ", orthographic" : ", perspective");
                std::printf("[plane] %s %s %s %s: max |AO - 1| = %.5f at (%d, %d)\n", method, units, resolution,
                            ortho ? "orthographic" : "perspective", worst, int(at % 160), int(at / 160));
            }
    }
}

TEST(SsaoAnalytic, FloorAtTheFootOfAWallMatchesCosineWeightedAO) {
    const int size = 400;
    const Camera cam = lookAt({3.2, 2.6, 3.5}, {0.6, 0.2, 0}, size, size, 50);
    const auto z = depthImage(cam, cornerHit);
    const double R = 1.0;
    // Screen-space AO can only see what is on screen: the occluding part of
    // the wall (height R, |z| <= R) must be in view.
    for (const Vec3& p : {Vec3{0, R, -R}, Vec3{0, R, R}, Vec3{0, 0, -R}}) {
        double px, py;
        projectPoint(cam, p, px, py);
        ASSERT_TRUE(px > 0 && py > 0 && px < size && py < size);
    }
    // Horizon: exact up to step discretisation. Hemisphere: a point test counts
    // 1 - (t/R)^3 of a ray that hits at t instead of 1, so it is expected to
    // under-occlude by up to ~0.085 (at d/R = 0.5) on this scene.
    struct Case {
        const char* method;
        double tolerance;
        const char* resolution;
    };
    for (const Case& c : {Case{"horizon", 0.05, "full"}, Case{"hemisphere", 0.10, "full"},
                          Case{"horizon", 0.05, "half"}, Case{"hemisphere", 0.10, "half"}}) {
        const BufferPtr out = runSsao(z, {{"method", {Value(c.method)}},
                                          {"resolution", {Value(c.resolution)}},
                                          {"radiusUnits", {Value("world")}},
                                          {"radius", {Value(R)}},
                                          {"falloff", {Value(0.0)}},
                                          {"blurRadius", {Value(0)}},
                                          {"samples", {Value(std::int64_t(64))}},
                                          {"slices", {Value(std::int64_t(16))}},
                                          {"steps", {Value(std::int64_t(16))}}});
        const float* ao = out->hostFloat("AO");
        double worst = 0;
        for (double k : {0.1, 0.25, 0.5, 0.75, 1.0, 1.5}) {
            double px, py;
            projectPoint(cam, {k * R, 0, 0}, px, py);
            // Mean over a 5x5 patch of floor pixels against the mean of their
            // own references (each pixel's true distance to the wall).
            double got = 0, want = 0;
            int count = 0;
            for (int dy = -2; dy <= 2; ++dy)
                for (int dx = -2; dx <= 2; ++dx) {
                    const int x = int(px) + dx, y = int(py) + dy;
                    Vec3 o, d;
                    cam.ray(x + 0.5, y + 0.5, o, d);
                    const Vec3 hit = o + d * double(z->hostFloat("Z")[std::size_t(y) * size + x]);
                    if (std::fabs(hit.y) > 1e-3 || hit.x <= 0) continue;  // not floor
                    got += ao[std::size_t(y) * size + x];
                    want += 1.0 - cornerOcclusionClosedForm(hit.x / R);
                    ++count;
                }
            ASSERT_GT(count, 10);
            got /= count;
            want /= count;
            worst = std::max(worst, std::fabs(got - want));
            EXPECT_NEAR(got, want, c.tolerance) << c.method << " " << c.resolution << " at d/R = " << k;
            std::printf("[corner] %s %s d/R=%.2f: AO %.4f, reference %.4f, error %+.4f\n", c.method, c.resolution, k,
                        got, want, got - want);
        }
        std::printf("[corner] %s %s: max error %.4f\n", c.method, c.resolution, worst);
    }
}


// A step seen from straight above: its wall is edge-on, so the image has a
// depth edge along it and every horizon sample that reaches the wall
// straddles it and takes the nearest pixel's depth (the plateau's or the
// floor's). The horizon to the step's top edge is then the whole occluder
// (height h well below R: the edge lies within R of the receivers for all but
// a sliver of azimuths), so the floor's AO must match the quadrature up to
// the march's steps (the first sample past the edge lies up to R / steps
// beyond it: AO +0.041 at most, measured; taking the wrong one of the four
// pixels at the edge gives +0.055); and
// the plateau next to the edge, which nothing occludes, must stay 1 with the
// depth-aware blur on (its range weight keeps the dark floor out).
TEST(SsaoAnalytic, FloorBelowAStepSeenFromAboveMatchesCosineWeightedAO) {
    const double R = 1.0, h = 0.25;
    const int size = 256;
    const auto stepHit = [&](const Vec3& o, const Vec3& d) {
        const double top = planeHit(o, d, {0, h, 0}, {0, 1, 0});
        if (std::isfinite(top) && o.x + top * d.x >= 0) return top;
        const double floor = planeHit(o, d, {0, 0, 0}, {0, 1, 0});
        return std::isfinite(floor) && o.x + floor * d.x < 0 ? floor : std::numeric_limits<double>::infinity();
    };
    for (bool ortho : {true, false}) {
        Camera cam = lookAt({0, 4, 0}, {0, 0, 0}, size, size, 50);
        cam.up = {0, 0, -1};
        if (ortho) {
            cam.projection = Camera::Projection::Orthographic;
            cam.viewHeight = 4;
        }
        const auto z = depthImage(cam, stepHit);
        for (int blur : {0, 2}) {
            const BufferPtr out = runSsao(z, {{"resolution", {Value("full")}},
                                              {"radiusUnits", {Value("world")}},
                                              {"radius", {Value(R)}},
                                              {"falloff", {Value(0.0)}},
                                              {"blurRadius", {Value(std::int64_t(blur))}},
                                              {"slices", {Value(std::int64_t(16))}},
                                              {"steps", {Value(std::int64_t(16))}}});
            const float* ao = out->hostFloat("AO");
            // The mean over a column of floor pixels at x = -d (and over the
            // first plateau column), rows within 0.5 of the image centre.
            const auto column = [&](double x) {
                double px, py, sum = 0;
                projectPoint(cam, {x, x < 0 ? 0.0 : h, 0}, px, py);
                int count = 0;
                for (int y = size / 2 - size / 8; y < size / 2 + size / 8; ++y, ++count)
                    sum += ao[std::size_t(y) * size + std::size_t(px)];
                return sum / count;
            };
            for (double k : {0.1, 0.25, 0.5}) {
                const double want = 1.0 - stepOcclusionQuadrature(k * R, h, R);
                const double got = column(-k * R);
                EXPECT_NEAR(got, want, 0.045) << (ortho ? "orthographic" : "perspective") << ", blur " << blur
                                             << ", d/R = " << k;
                std::printf("[step] %s blur %d d/R=%.2f: AO %.4f, reference %.4f, error %+.4f\n",
                            ortho ? "orthographic" : "perspective", blur, k, got, want, got - want);
            }
            const double plateau = column(0.5 * cam.viewHeight / size);
            EXPECT_GT(plateau, 0.99) << (ortho ? "orthographic" : "perspective") << ", blur " << blur;
        }
    }
}
