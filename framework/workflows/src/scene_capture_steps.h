#pragma once
// What capturing a scene file and capturing its time series share
// (scene_capture.cpp, series_capture.cpp): loading the scene, or one step of
// it, whole or as this process's part; the writer's options; the threads.
#include <darkroom/workflows/capture.h>

#include <darkroom/scene/scene_file.h>
#include <darkroom/scene/scene_partition.h>
#include <darkroom/scene/time_series.h>

namespace darkroom::workflows::detail {

// The whole scene alone; over several processes, this one's part (each
// loads the same objects, holding a share of their primitives). Errors are
// InputError, the same on every process.
PartitionedScene loadScene(const std::string& path, ProcessGroup& group, const SceneLoadOptions& options = {});

// The writer's options: the request's, the scene's point lists as
// attachments (their contents into `attachments`), and the origin a resume
// compares (`scene.inputFiles`: every file it reads, all steps' for a series).
CinemaWriterOptions writerOptions(const SceneCapture& r, const SceneDescription& scene,
                                  std::map<std::string, std::string>& attachments);

// Worker threads of one process: the request's, or the machine's cores shared
// among the group's processes on it.
int threadsPerProcess(const SceneCapture& r, const ProcessGroup& group);

// A scene with time series (time_series.h) captured into one database:
// rows = steps x cameras, the series' columns first.
CaptureSummary captureSceneSeries(const SceneCapture& r, const SceneSeries& series, const Registry& registry,
                                  ProcessGroup& group);

}  // namespace darkroom::workflows::detail
