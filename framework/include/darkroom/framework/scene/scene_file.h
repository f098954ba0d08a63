#pragma once
// The capture scene file (YAML): objects (from mesh files or generators, each
// drawn as surface, lines or points, with the scalar fields to keep), cameras
// (a phi/theta grid or an explicit list) and the channels to store.
#include <darkroom/camera.h>
#include <darkroom/capture_backend.h>
#include <darkroom/export.h>
#include <darkroom/scene.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace darkroom {

// One camera of the sampling grid with the database parameters it stands for
// (e.g. {{"phi", 30}, {"theta", 45}}), in column order.
struct CameraSample {
    std::vector<std::pair<std::string, double>> parameters;
    Camera camera;
};

struct SceneDescription {
    std::string path;  // the scene file
    std::shared_ptr<Scene> scene;
    std::vector<CameraSample> cameras;
    CaptureRequest request;
    std::string backend = "embree";
};

// Parses the scene file and loads every object it names. Throws darkroom::Error
// naming file:line:column (YAML problems) or the mesh file (reader problems).
DARKROOM_API SceneDescription loadSceneFile(const std::string& path);
DARKROOM_API SceneDescription parseSceneFile(const std::string& yamlText, const std::string& sourceName,
                                             const std::string& baseDir);

}  // namespace darkroom
