// SSAO and the ray-traced AO reference on the stress scenes (issue 6), small
// enough for CI: where the methods hold they must match the closed-form AO
// of the scene, the reference must be unbiased within its own standard error,
// and where they are known to fail they must still produce finite AO in [0, 1].
// The numbers behind the thresholds: docs/accuracy-ao-normals.md.
#include "test_support.h"

#include <darkroom/capture_backend.h>
#include <darkroom/context.h>
#include <darkroom/error.h>
#include <darkroom/accuracy/metrics.h>
#include <darkroom/accuracy/reference.h>
#include <darkroom/core/run_filter.h>
#include <darkroom/accuracy/stress_scenes.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace darkroom;

namespace {

constexpr int kSize = 80;
using Inputs = std::map<std::string, std::vector<Value>>;

struct Captured {
    stress::StressScene scene;
    std::unique_ptr<CaptureBackend> backend;
    BufferPtr gbuffer;
};

std::unique_ptr<Context> context() {
    FilterRunOptions o;
    o.threads = 2;
    o.registry = &test::pluginRegistry();
    return makeStandaloneContext(o, "ao_accuracy");
}

Captured capture(const std::string& family, double knob, int size = kSize) {
    Captured c{stress::make(family, knob, {size, size}), test::pluginRegistry().createBackend("embree"), nullptr};
    if (!c.backend) throw Error("the embree capture backend is not built");
    c.backend->setScene(c.scene.scene);
    CaptureRequest r;
    r.normals = true;
    r.objectId = true;
    c.gbuffer = c.backend->render(c.scene.camera, r, *context());
    return c;
}

// SSAO with the world radius the scene is built for, as the accuracy sweep
// runs it (hard radius cut, no blur, so it estimates exactly the reference's
// quantity).
BufferPtr ssao(const Captured& c, const std::string& method, const std::string& geometry = "surface",
               Inputs extra = {}) {
    auto f = test::pluginRegistry().createFilter("SSAO");
    extra["image"] = {Value(c.gbuffer)};
    extra["method"] = {Value(method)};
    extra["geometry"] = {Value(geometry)};
    extra["radiusUnits"] = {Value("world")};
    extra["radius"] = {Value(c.scene.aoRadius)};
    extra["falloff"] = {Value(0.0)};
    extra["blurRadius"] = {Value(0)};
    FilterRunOptions o;
    o.threads = 2;
    return runFilter(*f, extra, o).outputs.at("image").asImage();
}

// Interior pixels (no depth or id discontinuity within 1 px) whose distance
// to the image border is at least the occlusion radius projected at their
// depth: screen-space AO cannot see occluders beyond the border, a failure
// covered separately.
std::vector<std::uint8_t> awayFromBorder(const Captured& c) {
    const metrics::EdgeMasks m = metrics::edgeMasks(*c.gbuffer);
    const Camera& cam = c.scene.camera;
    const float* z = c.gbuffer->requireFloat("Z");
    std::vector<std::uint8_t> mask(c.gbuffer->pixelCount(), 0);
    for (int y = 0; y < cam.height; ++y)
        for (int x = 0; x < cam.width; ++x) {
            const std::size_t i = std::size_t(y) * cam.width + x;
            if (!m.interior[i]) continue;
            const double r = c.scene.aoRadius / cam.pixelSizeAt(z[i]);
            mask[i] = x >= r && y >= r && cam.width - 1 - x >= r && cam.height - 1 - y >= r;
        }
    return mask;
}

// The scene's closed-form AO at every pixel's world point (1 on background).
std::vector<float> analytic(const Captured& c, reference::AoWeighting weighting) {
    const Camera& cam = c.scene.camera;
    const float* z = c.gbuffer->requireFloat("Z");
    std::vector<float> ao(c.gbuffer->pixelCount(), 1.0f);
    for (int y = 0; y < cam.height; ++y)
        for (int x = 0; x < cam.width; ++x) {
            const std::size_t i = std::size_t(y) * cam.width + x;
            if (std::isfinite(z[i]))
                ao[i] = float(c.scene.analyticAo(cam.worldPosition(x + 0.5, y + 0.5, z[i]), c.scene.aoRadius, weighting));
        }
    return ao;
}

struct ErrorStats {
    double meanAbs = 0, max = 0, bias = 0;
    std::size_t count = 0;
};

ErrorStats compare(const float* got, const std::vector<float>& want, const std::vector<std::uint8_t>& mask) {
    ErrorStats s;
    for (std::size_t i = 0; i < mask.size(); ++i) {
        if (!mask[i]) continue;
        const double d = double(got[i]) - want[i];
        s.meanAbs += std::fabs(d);
        s.bias += d;
        s.max = std::max(s.max, std::fabs(d));
        ++s.count;
    }
    if (s.count) s.meanAbs /= double(s.count), s.bias /= double(s.count);
    return s;
}

}  // namespace

TEST(AoAccuracy, HorizonOnAnOpenPlaneIsUnoccluded) {
    const Captured c = capture("plane", 0);
    ASSERT_TRUE(c.scene.analyticAo);
    const auto mask = awayFromBorder(c);
    const BufferPtr out = ssao(c, "horizon");
    const ErrorStats e = compare(out->requireFloat("AO"), analytic(c, reference::AoWeighting::Cosine), mask);
    ASSERT_GT(e.count, std::size_t(kSize * kSize / 4));
    std::printf("[plane] horizon: mean |AO - ref| %.5f, max %.5f over %zu px\n", e.meanAbs, e.max, e.count);
    EXPECT_LT(e.meanAbs, 0.02);
    EXPECT_LT(e.max, 0.02);
}

TEST(AoAccuracy, HorizonAtTheCornerMatchesTheClosedForm) {
    const Captured c = capture("corner", 0);
    ASSERT_TRUE(c.scene.analyticAo);
    const auto mask = awayFromBorder(c);
    const auto want = analytic(c, reference::AoWeighting::Cosine);
    const ErrorStats e = compare(ssao(c, "horizon")->requireFloat("AO"), want, mask);
    ASSERT_GT(e.count, std::size_t(kSize * kSize / 8));
    std::printf("[corner] horizon: mean |error| %.4f, bias %+.4f, max %.4f over %zu px\n", e.meanAbs, e.bias, e.max,
                e.count);
    EXPECT_LT(e.meanAbs, 0.02);
    EXPECT_LT(e.max, 0.06);  // 0.044 measured at 80 px

    // The hemisphere estimator's point test under-occludes (AO too light) by
    // up to ~0.09 at the corner (plugins/ssao/README.md): bias positive, bounded.
    const ErrorStats hs =
        compare(ssao(c, "hemisphere", "surface", {{"samples", {Value(32)}}})->requireFloat("AO"), want, mask);
    std::printf("[corner] hemisphere: mean |error| %.4f, bias %+.4f, max %.4f\n", hs.meanAbs, hs.bias, hs.max);
    EXPECT_GT(hs.bias, 0.0);
    EXPECT_LT(hs.bias, 0.10);
    EXPECT_LT(hs.meanAbs, 0.10);
}

// The ray-traced reference against the corner's closed form, both weightings:
// the mean difference must lie within 4 standard errors of the mean, and
// hardly any pixel may miss its own 4-standard-error band.
TEST(AoAccuracy, RayTracedReferenceMatchesTheCornerWithinItsStandardError) {
    const Captured c = capture("corner", 0, 64);
    auto ctx = context();
    for (auto weighting : {reference::AoWeighting::Cosine, reference::AoWeighting::Uniform}) {
        reference::AoOptions o;
        o.weighting = weighting;
        o.radius = c.scene.aoRadius;
        o.samples = 256;
        const BufferPtr ref = reference::ambientOcclusion(*c.backend, c.scene.camera, o, *ctx);
        const auto want = analytic(c, weighting);
        const float* ao = ref->requireFloat("AO");
        const float* se = ref->requireFloat("AO.stderr");
        const float* z = c.gbuffer->requireFloat("Z");
        double sumDiff = 0, sumVar = 0;
        std::size_t n = 0, outside = 0;
        for (std::size_t i = 0; i < ref->pixelCount(); ++i) {
            if (!std::isfinite(z[i])) continue;
            const double d = double(ao[i]) - want[i];
            sumDiff += d;
            sumVar += double(se[i]) * se[i];
            // One ray's worth of slack: a pixel whose rays all agreed reports
            // a standard error of 0.
            outside += std::fabs(d) > 4.0 * se[i] + 1.0 / o.samples;
            ++n;
        }
        ASSERT_GT(n, std::size_t(64 * 64 / 4));
        const double meanDiff = sumDiff / double(n), seMean = std::sqrt(sumVar) / double(n);
        std::printf("[reference %s] mean difference %+.5f, standard error of the mean %.5f, %zu of %zu px outside 4 se\n",
                    reference::toString(weighting), meanDiff, seMean, outside, n);
        EXPECT_LE(std::fabs(meanDiff), 4.0 * seMean) << reference::toString(weighting);
        EXPECT_LE(double(outside), 0.01 * double(n)) << reference::toString(weighting);
    }
}

TEST(AoAccuracy, FailureRegimesStayFiniteAndInRange) {
    struct Case {
        const char* family;
        double knob;
    };
    for (const Case& k : {Case{"particles", 0.5}, Case{"particles", 20}, Case{"streamlines", 0.25}, Case{"slabs", 0.05},
                          Case{"grazing", 89}, Case{"border", 0}}) {
        const Captured c = capture(k.family, k.knob, 64);
        for (const char* method : {"horizon", "hemisphere"})
            for (const char* geometry : {"surface", "points"}) {
                const BufferPtr out = ssao(c, method, geometry);
                const float* ao = out->requireFloat("AO");
                std::size_t bad = 0, occluded = 0;
                for (std::size_t i = 0; i < out->pixelCount(); ++i) {
                    bad += !(ao[i] >= 0.0f && ao[i] <= 1.0f);  // NaN fails too
                    occluded += ao[i] < 1.0f;
                }
                EXPECT_EQ(bad, 0u) << c.scene.name << " " << method << " " << geometry;
                std::printf("[%s] %s %s: %zu px occluded\n", c.scene.name.c_str(), method, geometry, occluded);
            }
    }
}
