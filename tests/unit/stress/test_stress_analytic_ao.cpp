// The analytic AO of the plane, corner, grazing and stripes scenes agrees
// with ray-traced AO of the same scenes (reference::ambientOcclusion through
// the Embree backend; skipped when this build has none): the geometry is
// large enough that nothing outside the closed form's model shows up.
#include <darkroom/capture_backend.h>
#include <darkroom/error.h>
#include <darkroom/accuracy/reference.h>
#include <darkroom/core/registry.h>
#include <darkroom/core/run_filter.h>
#include <darkroom/accuracy/stress_scenes.h>

#include <gtest/gtest.h>

#include "test_support.h"

#include <cmath>
#include <set>

using namespace darkroom;
using reference::AoWeighting;

namespace {

std::unique_ptr<CaptureBackend> embree() {
    try {
        return test::pluginRegistry().createBackend("embree");
    } catch (const Error&) {
        return nullptr;
    }
}

TEST(StressAnalyticAo, OnlyTheFamiliesWithAClosedFormHaveOne) {
    const std::set<std::string> closed = {"plane", "corner", "grazing", "stripes"};
    for (const auto& family : stress::families()) {
        const auto s = stress::make(family, stress::knobValues(family).front(), {16, 16});
        EXPECT_EQ(bool(s.analyticAo), closed.count(family) == 1) << family;
    }
}

void compareWithRayTraced(const std::string& family, AoWeighting weighting) {
    auto backend = embree();
    if (!backend) GTEST_SKIP() << "no embree capture backend in this build";
    const auto s = stress::make(family, stress::knobValues(family).front(), {24, 24});
    ASSERT_TRUE(s.analyticAo);
    backend->setScene(s.scene);
    reference::AoOptions options;
    options.weighting = weighting;
    options.radius = s.aoRadius;
    options.samples = 512;
    FilterRunOptions run;
    run.threads = 2;
    auto ctx = makeStandaloneContext(run, "stress-ao-test");
    const BufferPtr ao = reference::ambientOcclusion(*backend, s.camera, options, *ctx);
    const float *z = ao->requireFloat("Z"), *traced = ao->requireFloat("AO"), *err = ao->requireFloat("AO.stderr");
    double sumAbs = 0, lo = 1;
    int n = 0;
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 24; ++x) {
            const std::size_t i = std::size_t(y) * 24 + x;
            if (!std::isfinite(z[i])) continue;
            const double exact = s.analyticAo(s.camera.worldPosition(x + 0.5, y + 0.5, z[i]), s.aoRadius, weighting);
            // Five standard errors plus a little for the hit point's float
            // rounding and the lifted ray origins.
            EXPECT_NEAR(traced[i], exact, 5.0 * err[i] + 0.01) << family << " pixel " << x << ", " << y;
            sumAbs += std::abs(traced[i] - exact);
            lo = std::min(lo, exact);
            ++n;
        }
    ASSERT_GT(n, 0);
    EXPECT_LT(sumAbs / n, 0.01) << family;
    if (family == "corner") {
        EXPECT_LT(lo, 0.6);  // the joint is in view: there is occlusion to test
    }
}

TEST(StressAnalyticAo, CornerCosineMatchesRayTracing) { compareWithRayTraced("corner", AoWeighting::Cosine); }
TEST(StressAnalyticAo, CornerUniformMatchesRayTracing) { compareWithRayTraced("corner", AoWeighting::Uniform); }
TEST(StressAnalyticAo, PlaneMatchesRayTracing) { compareWithRayTraced("plane", AoWeighting::Cosine); }
TEST(StressAnalyticAo, GrazingMatchesRayTracing) { compareWithRayTraced("grazing", AoWeighting::Cosine); }
TEST(StressAnalyticAo, StripesMatchesRayTracing) { compareWithRayTraced("stripes", AoWeighting::Uniform); }

}  // namespace
