#pragma once
// Drives the registered "embree" backend outside any graph.
#include <darkroom/capture_backend.h>
#include <darkroom/core/registry.h>
#include <darkroom/core/run_filter.h>
#include <gtest/gtest.h>

#include "test_support.h"

#include <memory>

namespace darkroom::test {

inline std::unique_ptr<CaptureBackend> embreeBackend() {
    auto backend = pluginRegistry().createBackend("embree");
    EXPECT_TRUE(backend) << "the embree backend is not registered";
    return backend;
}

inline BufferPtr capture(std::shared_ptr<const Scene> scene, const Camera& camera, const CaptureRequest& request,
                         int threads = 1) {
    auto backend = embreeBackend();
    backend->setScene(std::move(scene));
    FilterRunOptions options;
    options.threads = threads;
    auto ctx = makeStandaloneContext(options, "capture-test");
    return backend->render(camera, request, *ctx);
}

inline std::shared_ptr<const Scene> sceneOf(std::vector<SceneObject> objects) {
    auto s = std::make_shared<Scene>();
    s->objects = std::move(objects);
    return s;
}

}  // namespace darkroom::test
