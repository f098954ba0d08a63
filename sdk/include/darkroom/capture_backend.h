#pragma once
#include <darkroom/buffer.h>
#include <darkroom/camera.h>
#include <darkroom/context.h>
#include <darkroom/export.h>
#include <darkroom/scene.h>

#include <memory>
#include <string>
#include <vector>

namespace darkroom {

// Which G-buffer channels to render. Depth ("Z", planar view depth, +inf on
// background) is always produced; everything else only on request, since a
// database should store no more than shading needs.
struct CaptureRequest {
    std::vector<std::string> scalars;  // field names; NaN where an object lacks the field
    bool normals = false;              // world-space geometric normals "N.x", "N.y", "N.z"
    bool objectId = false;             // "objectId" (uint32, index into Scene::objects; ~0u background)
    bool primitiveId = false;          // "primitiveId" (uint32)
};

// Renders G-buffers of a scene for a camera. Implemented by capture plugins
// (e.g. capture-embree).
class DARKROOM_API CaptureBackend {
public:
    virtual ~CaptureBackend();

    // Builds acceleration structures. The scene is kept alive by the backend
    // and its arrays may be shared with the ray tracer.
    virtual void setScene(std::shared_ptr<const Scene> scene) = 0;

    // Renders one view. Allocates through ctx and honours its cancellation and
    // thread pool. The returned buffer carries `camera` in its metadata.
    virtual BufferPtr render(const Camera& camera, const CaptureRequest& request, Context& ctx) = 0;
};

}  // namespace darkroom
