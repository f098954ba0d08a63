#include "capture_filter.h"

#include <darkroom/error.h>
#include <darkroom/framework/scene/scene_file.h>

#include <sstream>

namespace darkroom {

namespace {

// "a, b ,c" -> {"a", "b", "c"}; empty items are dropped.
std::vector<std::string> splitList(const std::string& text) {
    std::vector<std::string> out;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ',')) {
        const auto b = item.find_first_not_of(" \t"), e = item.find_last_not_of(" \t");
        if (b != std::string::npos) out.push_back(item.substr(b, e - b + 1));
    }
    return out;
}

}  // namespace

struct CaptureFilter::Cache {
    std::string path;
    std::filesystem::file_time_type mtime;
    std::string backendType;
    std::unique_ptr<SceneDescription> description;
    std::unique_ptr<CaptureBackend> backend;
};

CaptureFilter::CaptureFilter() = default;
CaptureFilter::~CaptureFilter() = default;

PortList CaptureFilter::ports() const {
    PortList p;
    p.pathIn("scene", "", "Scene file (YAML) naming the objects, cameras and channels to capture");
    p.stringIn("backend", "embree", "Capture backend type, e.g. \"embree\"");
    p.intIn("camera", 0, 0, 1 << 30, "Index of the scene file's camera to render (in the order the file lists them)");
    p.intIn("width", 0, 0, 1 << 15, "Image width in pixels; 0 keeps the scene file's");
    p.intIn("height", 0, 0, 1 << 15, "Image height in pixels; 0 keeps the scene file's");
    p.stringIn("scalars", "", "Comma-separated scalar fields to render; empty keeps the scene file's list");
    p.boolIn("normals", false, "Also render normals (N.x, N.y, N.z), in addition to what the scene file asks for");
    p.boolIn("ids", false, "Also render objectId and primitiveId, in addition to what the scene file asks for");
    p.imageOut("image", "The G-buffer: Z (planar depth, +inf on background), scalars, optional normals and ids; "
                        "the camera travels in its metadata");
    return p;
}

void CaptureFilter::execute(Context& ctx) {
    const std::string& sceneArg = ctx.getString("scene");
    if (sceneArg.empty()) throw Error("Capture: no scene file given (input 'scene')");
    const std::string path = ctx.resolveInputPath(sceneArg);
    std::error_code ec;
    const auto mtime = std::filesystem::last_write_time(path, ec);
    if (ec) throw Error("Capture: cannot read scene file '" + path + "': " + ec.message());
    const std::string backendType = ctx.getString("backend");

    // Reload when the file changed on disk; rebuild the BVH only when the
    // scene or the backend changed.
    if (!cache_ || cache_->path != path || cache_->mtime != mtime) {
        auto fresh = std::make_unique<Cache>();
        fresh->path = path;
        fresh->mtime = mtime;
        fresh->description = std::make_unique<SceneDescription>(loadSceneFile(path));
        cache_ = std::move(fresh);
    }
    if (!cache_->backend || cache_->backendType != backendType) {
        cache_->backend.reset();
        auto backend = ctx.createBackend(backendType);
        if (!backend) throw Error("Capture: backend '" + backendType + "' could not be created");
        backend->setScene(cache_->description->scene);
        cache_->backend = std::move(backend);
        cache_->backendType = backendType;
    }

    const SceneDescription& d = *cache_->description;
    const std::int64_t index = ctx.getInt("camera");
    if (d.cameras.empty()) throw Error("Capture: scene file '" + path + "' defines no cameras");
    if (index < 0 || index >= std::int64_t(d.cameras.size()))
        throw Error("Capture: camera " + std::to_string(index) + " does not exist; scene file '" + path + "' has " +
                    std::to_string(d.cameras.size()) + " cameras (0.." + std::to_string(d.cameras.size() - 1) + ")");
    Camera camera = d.cameras[std::size_t(index)].camera;
    if (const auto w = ctx.getInt("width"); w > 0) camera.width = int(w);
    if (const auto h = ctx.getInt("height"); h > 0) camera.height = int(h);

    CaptureRequest request = d.request;
    if (const auto list = splitList(ctx.getString("scalars")); !list.empty()) request.scalars = list;
    request.normals = request.normals || ctx.getBool("normals");
    if (ctx.getBool("ids")) request.objectId = request.primitiveId = true;

    BufferPtr image = cache_->backend->render(camera, request, ctx);
    ctx.setOutput("image", std::move(image));
}

}  // namespace darkroom
