// `darkroom capture`'s whole job, alone or over processes, for every front end.
#include "scene_capture_steps.h"

#include <darkroom/error.h>
#include <darkroom/core/registry.h>
#include <darkroom/core/run_filter.h>
#include <darkroom/scene/scene_file.h>
#include <darkroom/scene/scene_partition.h>
#include <darkroom/workflows/capture_origin.h>

#include <algorithm>
#include <chrono>
#include <thread>

namespace darkroom::workflows {

namespace detail {

PartitionedScene loadScene(const std::string& path, ProcessGroup& group, const SceneLoadOptions& options) {
    try {
        if (group.size() > 1) return loadSceneFilePart(path, group, options);
        PartitionedScene whole;
        whole.description = loadSceneFile(path, options);
        return whole;
    } catch (const InputError&) {
        throw;
    } catch (const Error& e) {
        throw InputError(e.what());
    }
}

CinemaWriterOptions writerOptions(const SceneCapture& r, const SceneDescription& scene,
                                  std::map<std::string, std::string>& attachments) {
    CinemaWriterOptions wo;
    wo.overwrite = r.overwrite;
    wo.resume = r.resume;
    wo.image.compression = r.compression;
    wo.image.halfFloat = r.half;
    attachments = pointListAttachments(scene, wo);
    wo.origin = captureOrigin(r.scene, scene, r.compression, r.half);
    return wo;
}

int threadsPerProcess(const SceneCapture& r, const ProcessGroup& group) {
    if (r.threads > 0 || group.size() == 1) return r.threads;
    const int cores = int(std::thread::hardware_concurrency());
    return std::max(1, cores / std::max(1, group.onThisNode()));
}

}  // namespace detail

using namespace detail;

CaptureSummary captureSceneFile(const SceneCapture& r, const Registry& registry, ProcessGroup& group) {
    // A scene with time series is captured step by step (series_capture.cpp).
    SceneSeries series;
    std::string scanError;
    try {
        series = scanSceneSeries(r.scene);
    } catch (const Error& e) {
        scanError = e.what();
    }
    if (const std::string e = group.agreedError(scanError); !e.empty()) throw InputError(e);
    if (!series.steps.empty()) return captureSceneSeries(r, series, registry, group);

    const auto start = std::chrono::steady_clock::now();
    const auto since = [](std::chrono::steady_clock::time_point t) {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
    };
    const PartitionedScene part = loadScene(r.scene, group);
    const double sceneSeconds = since(start);
    const SceneDescription& scene = part.description;
    if (r.warn)
        for (const auto& w : scene.warnings) r.warn(w);
    if (scene.cameras.empty()) throw InputError(r.scene + ": the scene has no cameras");

    std::string error;
    double setupSeconds = 0, firstRaySeconds = 0;
    std::unique_ptr<CaptureBackend> backend;
    CinemaWriterOptions wo;
    CaptureSettings settings;
    try {
        backend = registry.createBackend(scene.backend);
        const auto setup = std::chrono::steady_clock::now();
        backend->setScene(scene.scene);
        setupSeconds = since(setup);
        wo = writerOptions(r, scene, settings.attachments);
    } catch (const Error& e) {
        error = e.what();
    }
    if (const std::string e = group.agreedError(error); !e.empty()) throw InputError(e);

    std::vector<std::string> columns;
    for (const auto& [k, v] : scene.cameras.front().parameters) columns.push_back(k);
    std::unique_ptr<CinemaWriter> writer;
    settings.openDatabase = [&]() -> CinemaWriter& {
        writer = std::make_unique<CinemaWriter>(r.output, columns, wo);
        return *writer;
    };
    settings.request = scene.request;
    settings.primitiveOffsets = part.primitiveOffset;
    settings.progress = r.progress;
    settings.cancel = r.cancel;
    FilterRunOptions ro;
    ro.threads = threadsPerProcess(r, group);
    ro.registry = &registry;
    const std::unique_ptr<Context> ctx = makeStandaloneContext(ro, "capture");
    const RenderFn render = [&](const Camera& camera, const CaptureRequest& request) {
        if (firstRaySeconds == 0) firstRaySeconds = since(start);
        return backend->render(camera, request, *ctx);
    };
    CaptureSummary summary = captureEntries(captureEntriesOf(scene), render, group, settings);
    if (writer) writer->finish();
    summary.sceneSeconds = sceneSeconds;
    summary.setupSeconds = setupSeconds;
    summary.firstRaySeconds = firstRaySeconds;
    return summary;
}

}  // namespace darkroom::workflows
