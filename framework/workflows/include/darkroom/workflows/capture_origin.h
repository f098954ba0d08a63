#pragma once
// What a capture is made from, recorded in its database so that `capture
// --resume` refuses to complete it from a changed scene file or other options
// (docs/capture.md): the scene file's content, the mesh and volume files it
// reads (name, size, modification time), the resolution, the cameras,
// the channels asked for, the backend, the compression and --half.
#include <darkroom/export.h>
#include <darkroom/data/cinema/writer.h>
#include <darkroom/scene/scene_file.h>

#include <string>
#include <vector>

namespace darkroom::workflows {

DARKROOM_API std::vector<CinemaOriginItem> captureOrigin(const std::string& sceneFile, const SceneDescription& scene,
                                            const std::string& compression, bool half);

}  // namespace darkroom::workflows
