#pragma once
#include <darkroom/buffer.h>
#include <darkroom/camera.h>
#include <darkroom/context.h>
#include <darkroom/export.h>
#include <darkroom/scene.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace darkroom {

// Which G-buffer channels to render. Depth ("Z", planar view depth, +inf on
// background) is always produced; everything else only on request, since a
// database should store no more than shading needs.
struct CaptureRequest {
    std::vector<std::string> scalars;  // field names; NaN where an object lacks the field
    bool normals = false;              // world-space normals "N.x", "N.y", "N.z" (a surface's vertex
                                       // normals interpolated where it carries them, else geometric)
    bool objectId = false;             // "objectId" (uint32, index into Scene::objects; ~0u background)
    bool primitiveId = false;          // "primitiveId" (uint32)
    int layers = 1;                    // surface crossings kept per pixel, 1 to kMaxLayers: the K nearest,
                                       // front to back, named as darkroom/layers.h says (layer1.Z, ...)
    static constexpr int kMaxLayers = 16;
};

// Rays in world space for CaptureBackend::trace and ::occluded. Directions
// need not be unit length: t is measured in units of each direction's length
// (so a primary ray whose forward component is 1 reports planar depth).
struct RayBatch {
    std::vector<float> origins;     // x, y, z per ray
    std::vector<float> directions;  // x, y, z per ray
    std::vector<float> tFar;        // per ray; empty = unbounded
    float tNear = 0.0f;             // the same for every ray

    std::size_t size() const { return origins.size() / 3; }
    void reserve(std::size_t n) {
        origins.reserve(3 * n);
        directions.reserve(3 * n);
    }
    void add(const Vec3& origin, const Vec3& direction) {
        origins.insert(origins.end(), {float(origin.x), float(origin.y), float(origin.z)});
        directions.insert(directions.end(), {float(direction.x), float(direction.y), float(direction.z)});
    }
    void add(const Vec3& origin, const Vec3& direction, float far) {
        add(origin, direction);
        tFar.push_back(far);
    }
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

    // Reference queries, for ray-traced ground truth (ambient occlusion, thin
    // lens depth of field, supersampling; see darkroom/accuracy/reference.h). A
    // backend that cannot answer them keeps these defaults, which throw
    // darkroom::Error.
    //
    // One G-buffer sample per ray: a buffer `rays.size()` wide and 1 high with
    // the channels of `request`, computed exactly as render() computes a
    // pixel, except that "Z" is the ray parameter t of the first hit in
    // (tNear, tFar) (+inf on a miss) and no camera is attached. Normals face
    // against the ray.
    virtual BufferPtr trace(const RayBatch& rays, const CaptureRequest& request, Context& ctx);

    // Any-hit queries: hit[i] = 1 if any primitive lies on ray i within
    // (tNear, tFar), else 0. Resizes `hit` to rays.size().
    virtual void occluded(const RayBatch& rays, std::vector<std::uint8_t>& hit, Context& ctx);
};

}  // namespace darkroom
