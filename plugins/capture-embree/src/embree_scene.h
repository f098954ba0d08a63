#pragma once
// An Embree scene built from a darkroom::Scene. Kept free of Embree headers
// (the handles are Embree's own opaque struct types) so that the backend's
// other files and the benchmark can hold one without including Embree.
#include <darkroom/scene.h>

#include <memory>
#include <string>

struct RTCDeviceTy;
struct RTCSceneTy;

namespace darkroom::embree {

// One Embree device. Errors Embree reports are turned into darkroom::Error by
// check().
class Device {
public:
    Device();
    ~Device();
    Device(const Device&) = delete;
    Device& operator=(const Device&) = delete;
    RTCDeviceTy* handle() const { return device_; }
    // Throws darkroom::Error naming `what` if Embree recorded an error.
    void check(const std::string& what) const;

private:
    RTCDeviceTy* device_ = nullptr;
};

// The acceleration structure of one scene. Geometry ID i is scene object i.
// Vertex and index arrays are shared with Embree, not copied, so the scene is
// kept alive here for as long as the BVH exists.
class SceneBvh {
public:
    // Validates every object (indices in range, field sizes) and throws
    // darkroom::Error naming the object on bad input, since Embree itself
    // would read out of bounds.
    SceneBvh(std::shared_ptr<Device> device, std::shared_ptr<const Scene> scene);
    ~SceneBvh();
    SceneBvh(const SceneBvh&) = delete;
    SceneBvh& operator=(const SceneBvh&) = delete;

    RTCSceneTy* handle() const { return scene_; }
    const Scene& scene() const { return *source_; }

private:
    void build();
    std::shared_ptr<Device> device_;
    std::shared_ptr<const Scene> source_;
    RTCSceneTy* scene_ = nullptr;
};

// Primitives Embree sees for an object (triangles, segments or spheres).
// (SceneObject::primitiveCount() is not exported from the SDK library, so
// plugins cannot call it.)
std::size_t primitiveCountOf(const SceneObject& object);

// Throws darkroom::Error if an object cannot be handed to the ray tracer.
void validateObject(const SceneObject& object, std::size_t index);

}  // namespace darkroom::embree
