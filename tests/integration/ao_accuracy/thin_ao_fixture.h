#pragma once
// Shared by the thin-geometry AO accuracy tests (issue 31): a stress scene
// captured with normals, its 256-ray cosine-weighted reference, and the RMSE
// of a node's AO against it over the pixels with geometry, at a size CI
// affords (96 x 96; the reference's own noise is about 0.01 of the RMSE).
#include "test_support.h"

#include <darkroom/capture_backend.h>
#include <darkroom/context.h>
#include <darkroom/error.h>
#include <darkroom/accuracy/metrics.h>
#include <darkroom/accuracy/reference.h>
#include <darkroom/accuracy/stress_scenes.h>
#include <darkroom/core/run_filter.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace darkroom::test {

using NodeInputs = std::map<std::string, std::vector<Value>>;

struct ThinScene {
    stress::StressScene scene;
    BufferPtr gbuffer, reference;
    std::vector<std::uint8_t> geometry;  // pixels with finite depth
};

inline ThinScene thinScene(const std::string& family, double knob, int size = 96) {
    ThinScene t{stress::make(family, knob, {size, size}), nullptr, nullptr, {}};
    auto backend = pluginRegistry().createBackend("embree");
    if (!backend) throw Error("the embree capture backend is not built");
    backend->setScene(t.scene.scene);
    FilterRunOptions o;
    o.threads = 2;
    o.registry = &pluginRegistry();
    const auto ctx = makeStandaloneContext(o, "thin_ao_accuracy");
    CaptureRequest request;
    request.normals = true;
    t.gbuffer = backend->render(t.scene.camera, request, *ctx);
    reference::AoOptions ro;
    ro.radius = t.scene.aoRadius;
    ro.samples = 256;
    t.reference = reference::ambientOcclusion(*backend, t.scene.camera, ro, *ctx);
    const float* z = t.gbuffer->requireFloat("Z");
    t.geometry.resize(t.gbuffer->pixelCount());
    for (std::size_t i = 0; i < t.geometry.size(); ++i) t.geometry[i] = std::isfinite(z[i]);
    return t;
}

// Runs node `type` on the scene's G-buffer with `in` (plus image) and returns
// its AO's RMSE against the reference.
inline double aoRmse(const ThinScene& t, const std::string& type, NodeInputs in) {
    auto f = pluginRegistry().createFilter(type);
    in["image"] = {Value(t.gbuffer)};
    FilterRunOptions o;
    o.threads = 2;
    const BufferPtr out = runFilter(*f, in, o).outputs.at("image").asImage();
    return metrics::rmse(out->requireFloat("AO"), t.reference->requireFloat("AO"), t.geometry.size(),
                         t.geometry.data())
        .value;
}

// SSAO as the accuracy sweep runs it: world radius of the scene, hard cut,
// no blur; `method` and any extra settings.
inline double ssaoRmse(const ThinScene& t, const std::string& method, NodeInputs extra = {}) {
    extra["method"] = {Value(method)};
    extra["radiusUnits"] = {Value("world")};
    extra["radius"] = {Value(t.scene.aoRadius)};
    extra["falloff"] = {Value(0.0)};
    extra["blurRadius"] = {Value(0)};
    const double e = aoRmse(t, "SSAO", extra);
    std::printf("%s SSAO %s: RMSE %.4f\n", t.scene.name.c_str(), method.c_str(), e);
    return e;
}

}  // namespace darkroom::test
