// PointListAO against ray-traced AO on the thin stress scenes (issue 31), at
// a size CI affords: where screen-space AO fails on particles and lines a
// pixel or two wide (known failures, pinned here too), occlusion from the
// list the capture stores matches the reference. The numbers behind the
// thresholds: docs/accuracy.md (the ao sweep's "point list" rows).
#include "test_support.h"

#include <darkroom/capture_backend.h>
#include <darkroom/context.h>
#include <darkroom/error.h>
#include <darkroom/accuracy/metrics.h>
#include <darkroom/accuracy/reference.h>
#include <darkroom/accuracy/stress_scenes.h>
#include <darkroom/core/run_filter.h>
#include <darkroom/data/formats/point_list.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace darkroom;

namespace {

constexpr int kSize = 96;
using Inputs = std::map<std::string, std::vector<Value>>;

struct Measured {
    double listRmse = 0, horizonRmse = 0, referenceStderr = 0;
};

std::unique_ptr<Context> context() {
    FilterRunOptions o;
    o.threads = 2;
    o.registry = &test::pluginRegistry();
    return makeStandaloneContext(o, "point_list_ao_accuracy");
}

BufferPtr run(const std::string& type, Inputs in) {
    auto f = test::pluginRegistry().createFilter(type);
    FilterRunOptions o;
    o.threads = 2;
    return runFilter(*f, in, o).outputs.at("image").asImage();
}

// RMSE over the pixels with geometry, of PointListAO (the scene's own thin
// object as the list) and of SSAO horizon 4 x 8 at the defaults the sweep
// uses, against 256 cosine-weighted rays per pixel.
Measured measure(const std::string& family, double knob) {
    const stress::StressScene scene = stress::make(family, knob, {kSize, kSize});
    auto backend = test::pluginRegistry().createBackend("embree");
    if (!backend) throw Error("the embree capture backend is not built");
    backend->setScene(scene.scene);
    CaptureRequest request;
    request.normals = true;
    const auto ctx = context();
    const BufferPtr g = backend->render(scene.camera, request, *ctx);
    reference::AoOptions ro;
    ro.radius = scene.aoRadius;
    ro.samples = 256;
    const BufferPtr ref = reference::ambientOcclusion(*backend, scene.camera, ro, *ctx);

    test::TempDir dir;
    for (const SceneObject& o : scene.scene->objects)
        if (o.representation != Representation::Surface) test::writeText(dir.file("list.csv"), pointListCsv(o));
    const BufferPtr list = run("PointListAO", {{"image", {Value(g)}},
                                               {"points", {Value(dir.file("list.csv"))}},
                                               {"radiusUnits", {Value("world")}},
                                               {"radius", {Value(scene.aoRadius)}}});
    const BufferPtr horizon = run("SSAO", {{"image", {Value(g)}},
                                           {"radiusUnits", {Value("world")}},
                                           {"radius", {Value(scene.aoRadius)}},
                                           {"falloff", {Value(0.0)}},
                                           {"blurRadius", {Value(0)}}});
    const float* z = g->requireFloat("Z");
    std::vector<std::uint8_t> mask(g->pixelCount());
    double se = 0;
    for (std::size_t i = 0; i < mask.size(); ++i) {
        mask[i] = std::isfinite(z[i]);
        if (mask[i]) se += ref->requireFloat("AO.stderr")[i];
    }
    Measured m;
    m.listRmse = metrics::rmse(list->requireFloat("AO"), ref->requireFloat("AO"), mask.size(), mask.data()).value;
    m.horizonRmse = metrics::rmse(horizon->requireFloat("AO"), ref->requireFloat("AO"), mask.size(), mask.data()).value;
    m.referenceStderr = se / double(std::count(mask.begin(), mask.end(), 1));
    std::printf("%s %g: point list RMSE %.4f, horizon %.4f, reference stderr %.4f\n", family.c_str(), knob, m.listRmse,
                m.horizonRmse, m.referenceStderr);
    return m;
}

}  // namespace

TEST(PointListAoAccuracy, SubPixelParticlesMatchRayTracing) {
    // 96 x 96 against 256 rays (whose own noise is about 0.01 of the RMSE).
    for (const double radiusPx : {0.5, 2.0}) {
        const Measured m = measure("particles", radiusPx);
        EXPECT_LE(m.listRmse, 0.03) << radiusPx;
        // The known failure it replaces: the depth buffer's columns.
        EXPECT_LE(m.listRmse, m.horizonRmse / 3) << radiusPx;
    }
    EXPECT_GE(measure("particles", 0.5).horizonRmse, 0.15);
}

TEST(PointListAoAccuracy, ThinLinesMatchRayTracing) {
    for (const double widthPx : {0.5, 2.0}) {
        const Measured m = measure("streamlines", widthPx);
        EXPECT_LE(m.listRmse, 0.05) << widthPx;
        EXPECT_LE(m.listRmse, m.horizonRmse / 2.5) << widthPx;
        EXPECT_GE(m.horizonRmse, 0.1) << widthPx;
    }
}

TEST(PointListAoAccuracy, LinesAsWideAsAGoodPartOfTheRadiusAreItsKnownFailure) {
    // The thin-line model assumes r << distance; at 16 px (a third of R
    // across) it under-occludes next to the lines (docs/accuracy.md).
    const Measured m = measure("streamlines", 16.0);
    EXPECT_GE(m.listRmse, 0.05);
    EXPECT_LE(m.listRmse, 0.15);  // still an estimate, not garbage
}
