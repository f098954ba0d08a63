// The Normals pass on the stress scenes (issue 6), small enough for CI: on
// smooth surfaces the default reconstruction from depth matches the captured
// geometric normals to within a degree; where it is known to fail (sub-pixel
// features, thin slabs, grazing views, depth steps, the image border) it must
// still write unit normals on geometry and NaN exactly on background.
// The numbers behind the thresholds: docs/accuracy-ao-normals.md.
#include "test_support.h"

#include <darkroom/capture_backend.h>
#include <darkroom/context.h>
#include <darkroom/error.h>
#include <darkroom/accuracy/metrics.h>
#include <darkroom/core/run_filter.h>
#include <darkroom/accuracy/stress_scenes.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace darkroom;

namespace {

constexpr int kSize = 96;

struct Captured {
    stress::StressScene scene;
    BufferPtr gbuffer;  // Z, N.*, objectId
    BufferPtr depth;    // Z and the camera only: the pass's input
};

Captured capture(const std::string& family, double knob, int size = kSize) {
    Captured c{stress::make(family, knob, {size, size}), nullptr, nullptr};
    auto backend = test::pluginRegistry().createBackend("embree");
    if (!backend) throw Error("the embree capture backend is not built");
    backend->setScene(c.scene.scene);
    FilterRunOptions o;
    o.threads = 2;
    o.registry = &test::pluginRegistry();
    auto ctx = makeStandaloneContext(o, "normals_accuracy");
    CaptureRequest r;
    r.normals = true;
    r.objectId = true;
    c.gbuffer = backend->render(c.scene.camera, r, *ctx);
    // Without captured normals in the input, so the pass has to reconstruct.
    c.depth = backend->render(c.scene.camera, CaptureRequest{}, *ctx);
    return c;
}

BufferPtr normals(const Captured& c, const std::string& method) {
    auto f = test::pluginRegistry().createFilter("Normals");
    FilterRunOptions o;
    o.threads = 2;
    return runFilter(*f, {{"image", {Value(c.depth)}}, {"method", {Value(method)}}}, o).outputs.at("image").asImage();
}

}  // namespace

// Interior median bounds: a degree on the plane and the terrain; the gyroid's
// tunnels are only ~20 px wide at this size, so its curvature costs more
// (1.55 degrees measured at 96 px).
TEST(NormalsAccuracy, ExtrapolatedIsAccurateOnSmoothSurfaces) {
    struct Case {
        const char* family;
        double medianBound;
    };
    for (const auto& [family, medianBound] : {Case{"plane", 1.0}, Case{"terrain", 1.0}, Case{"gyroid", 2.0}}) {
        const Captured c = capture(family, 0);
        ASSERT_FALSE(c.depth->hasChannel("N.x"));
        const metrics::EdgeMasks m = metrics::edgeMasks(*c.gbuffer);
        const BufferPtr out = normals(c, "extrapolated");
        const metrics::AngularStats s = metrics::angularError(*out, *c.gbuffer, {"N.x", "N.y", "N.z"}, m.interior.data());
        std::printf("[%s] extrapolated, interior: mean %.3f, median %.3f, p95 %.3f deg over %zu px\n", family, s.mean,
                    s.median, s.p95, s.count);
        ASSERT_GT(s.count, std::size_t(kSize * kSize / 8)) << family;
        EXPECT_LT(s.median, medianBound) << family;
    }
}

TEST(NormalsAccuracy, FailureRegimesGiveUnitNormalsOnGeometryAndNaNOnBackground) {
    struct Case {
        const char* family;
        double knob;
    };
    for (const Case& k : {Case{"particles", 0.5}, Case{"streamlines", 0.25}, Case{"slabs", 0.05},
                          Case{"grazing", 89}, Case{"border", 0}, Case{"staircase", 4}}) {
        const Captured c = capture(k.family, k.knob, 64);
        const float* z = c.gbuffer->requireFloat("Z");
        for (const char* method : {"central", "nearest", "extrapolated"}) {
            const BufferPtr out = normals(c, method);
            const float* n[3] = {out->requireFloat("N.x"), out->requireFloat("N.y"), out->requireFloat("N.z")};
            std::size_t bad = 0, geometry = 0;
            for (std::size_t i = 0; i < out->pixelCount(); ++i) {
                if (std::isfinite(z[i])) {
                    ++geometry;
                    const double len = std::sqrt(double(n[0][i]) * n[0][i] + double(n[1][i]) * n[1][i] +
                                                 double(n[2][i]) * n[2][i]);
                    bad += !(std::fabs(len - 1.0) < 1e-4);  // NaN fails too
                } else {
                    bad += !(std::isnan(n[0][i]) && std::isnan(n[1][i]) && std::isnan(n[2][i]));
                }
            }
            EXPECT_GT(geometry, 0u) << c.scene.name;
            EXPECT_EQ(bad, 0u) << c.scene.name << " " << method;
        }
    }
}
