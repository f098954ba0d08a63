#include <darkroom/workflows/capture_origin.h>

#include "content_hash.h"

#include <darkroom/input_file.h>

#include <fmt/format.h>

#include <cstdint>
#include <filesystem>
#include <set>

namespace darkroom::workflows {

std::vector<CinemaOriginItem> captureOrigin(const std::string& sceneFile, const SceneDescription& scene,
                                            const std::string& compression, bool half) {
    const std::string scenePart = "the scene file", options = "the capture options";
    std::set<std::string> sizes;
    ContentHash poses;
    for (const auto& c : scene.cameras) {
        sizes.insert(fmt::format("{}x{}", c.camera.width, c.camera.height));
        for (const auto& [k, v] : c.parameters) {
            poses.add(k);
            poses.add(v);
        }
        const Camera& m = c.camera;
        for (double v : {m.position.x, m.position.y, m.position.z, m.forward.x, m.forward.y, m.forward.z, m.up.x,
                         m.up.y, m.up.z, m.fovYDegrees, m.viewHeight})
            poses.add(v);
        poses.add(m.projection == Camera::Projection::Perspective ? "perspective" : "orthographic");
    }
    std::string resolution;
    for (const auto& s : sizes) resolution += (resolution.empty() ? "" : ",") + s;
    std::string channels;
    auto addChannel = [&](const std::string& c) { channels += (channels.empty() ? "" : ",") + c; };
    for (const auto& s : scene.request.scalars) addChannel(s);
    // Geometric normals keep the name databases captured before smooth
    // normals existed have, so those resume; a smooth capture does not mix
    // with them, nor with one at another feature angle.
    if (scene.request.normals)
        addChannel(scene.normals.style == NormalsOptions::Style::Geometric
                       ? std::string("normals")
                       : fmt::format("smooth normals (feature angle {})", scene.normals.featureAngle));
    if (scene.request.objectId) addChannel("objectId");
    if (scene.request.primitiveId) addChannel("primitiveId");
    ContentHash content;
    content.add(readInputFile(sceneFile, "scene file"));
    // The files the scene reads, by name, size and modification time (the
    // quick check of make and rsync): hashing a 300-million-triangle mesh's
    // bytes would cost more than many captures.
    ContentHash files;
    for (const auto& f : scene.inputFiles) {
        std::error_code sizeError, timeError;
        const auto size = std::filesystem::file_size(f, sizeError);
        const auto time = std::filesystem::last_write_time(f, timeError);
        files.add(f);
        files.add(fmt::format("{} {}", sizeError ? 0 : size, timeError ? 0 : time.time_since_epoch().count()));
    }
    std::vector<CinemaOriginItem> origin = {
        {scenePart, "resolution", resolution.empty() ? "none" : resolution, false},
        {scenePart, "cameras", std::to_string(scene.cameras.size()), false},
        {scenePart, "channels", channels.empty() ? "depth only" : channels, false},
        {scenePart, "backend", scene.backend, false},
        {scenePart, "camera poses", poses.hex(), true},
        {scenePart, "content", content.hex(), true},
        {options, "compression", compression, false},
        {options, "half floats", half ? "yes" : "no", false},
    };
    // Only for scenes that read files, so the marker of a generated scene
    // stays what earlier versions wrote.
    if (!scene.inputFiles.empty())
        origin.push_back({"the mesh and volume files the scene reads", "name, size and time",
                          fmt::format("{} file{} {}", scene.inputFiles.size(), scene.inputFiles.size() == 1 ? "" : "s",
                                      files.hex()),
                          false});
    return origin;
}

}  // namespace darkroom::workflows
