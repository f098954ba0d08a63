// Normals against the true geometric normals captured by the embree backend on
// the demo isosurface: the discontinuity-aware methods must beat the central
// difference at depth edges and all must be accurate inside surfaces. Prints
// the table quoted in the README.
#include "accuracy.h"
#include "depth_scenes.h"

#include <darkroom/capture_backend.h>
#include <darkroom/scene/scene_file.h>

#include <gtest/gtest.h>

#include <cstdio>

using namespace darkroom;
using namespace darkroom::test;

namespace {

BufferPtr captureIsosurface(int size) {
    const std::string yaml = "objects:\n  - generator: isosurface\ncameras:\n  resolution: [" + std::to_string(size) + ", " +
                             std::to_string(size) + "]\n  grid: {phi: [30], theta: [20]}\nchannels:\n  normals: true\n";
    const SceneDescription d = parseSceneFile(yaml, "accuracy.yaml", ".");
    auto backend = pluginRegistry().createBackend("embree");
    if (!backend) return nullptr;
    backend->setScene(d.scene);
    FilterRunOptions o;
    auto ctx = makeStandaloneContext(o, "capture");
    return backend->render(d.cameras.at(0).camera, d.request, *ctx);
}

TEST(NormalsAccuracy, DiscontinuityAwareMethodsBeatCentralDifferencesAtEdges) {
    for (const int size : {256, 1024}) {
        const BufferPtr truth = captureIsosurface(size);
        if (!truth) GTEST_SKIP() << "the embree capture backend is not built";
        std::map<std::string, NormalAccuracy> acc;
        for (const std::string m : {"central", "nearest", "extrapolated"}) {
            const BufferPtr out = runPass("Normals", truth, {{"method", {Value(m)}}, {"replace", {Value(true)}}});
            acc[m] = compareNormals(*truth, *out);
            const auto& a = acc[m];
            std::printf("%4d^2 %-12s edges (%6zu px) mean %6.2f median %6.2f p95 %6.2f | interior (%7zu px) mean %5.2f median %5.2f p95 %5.2f deg\n",
                        size, m.c_str(), a.edges.count, a.edges.mean, a.edges.median, a.edges.p95, a.interior.count,
                        a.interior.mean, a.interior.median, a.interior.p95);
        }
        // At a silhouette the central difference mixes two surfaces; the
        // one-sided choices stay on the pixel's own surface.
        EXPECT_LT(acc["nearest"].edges.mean, 0.5 * acc["central"].edges.mean) << size;
        EXPECT_LT(acc["extrapolated"].edges.mean, 0.5 * acc["central"].edges.mean) << size;
        EXPECT_LT(acc["extrapolated"].edges.p95, acc["central"].edges.p95) << size;
        // Inside smooth surfaces all methods see the same surface: a few
        // degrees at most (the mesh is faceted: at 256² a pixel spans several facets).
        for (const auto& [m, a] : acc) EXPECT_LT(a.interior.median, 3.0) << m << " " << size;
        // Extrapolated falls back to central differences where both sides agree.
        EXPECT_LE(acc["extrapolated"].interior.mean, acc["nearest"].interior.mean * 1.05) << size;
    }
}

}  // namespace
