#include "capture.h"

#include <darkroom/error.h>
#include <darkroom/strings.h>
#include <darkroom/scene/scene_file.h>


namespace darkroom {

struct Capture::Cache {
    std::string path;
    std::filesystem::file_time_type mtime;
    std::string backendType;
    std::unique_ptr<SceneDescription> description;
    bool normalsLoaded = false;  // the scene was loaded ready for normals
    std::unique_ptr<CaptureBackend> backend;
};

Capture::Capture() = default;
Capture::~Capture() = default;

void Capture::execute(Context& ctx) {
    const std::string path = ctx.get(scene_);
    if (path.empty()) throw Error("no scene file given (input 'scene')");
    std::error_code ec;
    const auto mtime = std::filesystem::last_write_time(path, ec);
    if (ec) throw Error("cannot read scene file '" + path + "': " + ec.message());
    const std::string backendType = ctx.get(backend_);

    // Reload when the file changed on disk, or when normals are asked for
    // and the scene was loaded without preparing them (smooth normals need
    // vertex normals made while loading); rebuild the BVH only when the
    // scene or the backend changed.
    const bool normals = ctx.get(normals_);
    if (!cache_ || cache_->path != path || cache_->mtime != mtime || (normals && !cache_->normalsLoaded)) {
        auto fresh = std::make_unique<Cache>();
        fresh->path = path;
        fresh->mtime = mtime;
        SceneLoadOptions options;
        options.normals = normals;
        fresh->description = std::make_unique<SceneDescription>(loadSceneFile(path, options));
        fresh->normalsLoaded = normals || fresh->description->request.normals;
        cache_ = std::move(fresh);
    }
    if (!cache_->backend || cache_->backendType != backendType) {
        cache_->backend.reset();
        auto backend = ctx.createBackend(backendType);
        if (!backend) throw Error("backend '" + backendType + "' could not be created");
        backend->setScene(cache_->description->scene);
        cache_->backend = std::move(backend);
        cache_->backendType = backendType;
    }

    const SceneDescription& d = *cache_->description;
    const std::int64_t index = ctx.get(camera_);
    if (d.cameras.empty()) throw Error("scene file '" + path + "' defines no cameras");
    if (index < 0 || index >= std::int64_t(d.cameras.size()))
        throw Error("camera " + std::to_string(index) + " does not exist; scene file '" + path + "' has " +
                    std::to_string(d.cameras.size()) + " cameras (0.." + std::to_string(d.cameras.size() - 1) + ")");
    Camera camera = d.cameras[std::size_t(index)].camera;
    if (const auto w = ctx.get(width_); w > 0) camera.width = int(w);
    if (const auto h = ctx.get(height_); h > 0) camera.height = int(h);

    CaptureRequest request = d.request;
    if (const auto list = splitList(ctx.get(scalars_)); !list.empty()) request.scalars = list;
    request.normals = request.normals || normals;
    if (ctx.get(ids_)) request.objectId = request.primitiveId = true;

    ctx.set(result_, cache_->backend->render(camera, request, ctx));
}

}  // namespace darkroom
