#pragma once
// An Embree scene built from a darkroom::Scene. Kept free of Embree headers
// (the handles are Embree's own opaque struct types) so that the backend's
// other files and the benchmark can hold one without including Embree.
#include "bvh_settings.h"

#include <darkroom/scene.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

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

// One field of an object as the G-buffer writer reads it.
struct FieldView {
    std::string name;
    const float* values = nullptr;
    std::size_t count = 0;
    bool cell = false;
};

// One object as the ray tracer and the G-buffer writer read it: arrays that
// belong to someone else (a darkroom::Scene, or a simulation's own memory
// handed over through the in situ API), shared with Embree, never copied.
struct ObjectView {
    std::string name;
    Representation representation = Representation::Surface;
    // x, y, z at the start of each record; lines and points keep their
    // radius at offset 12 (Embree's FLOAT4), so their stride is at least 16.
    const float* vertices = nullptr;
    std::size_t vertexStride = 16;  // bytes
    std::size_t vertexCount = 0;
    // Surface: 3 per triangle; lines: the first vertex of each segment; points: none.
    const std::uint32_t* indices = nullptr;
    std::size_t primitiveCount = 0;
    // Primitive -> cell for cell fields; nullptr: primitive i is cell i.
    const std::uint32_t* primitiveCell = nullptr;
    // Surfaces: unit vertex normals, one x, y and z array, vertexCount long,
    // interpolated at each hit; nullptr: the triangles' own normals.
    const float* normals[3] = {nullptr, nullptr, nullptr};
    std::vector<FieldView> fields;

    const FieldView* field(const std::string& n) const {
        for (const auto& f : fields)
            if (f.name == n) return &f;
        return nullptr;
    }
    // Vertex i's x, y, z (and radius).
    const float* vertex(std::size_t i) const {
        return reinterpret_cast<const float*>(reinterpret_cast<const char*>(vertices) + i * vertexStride);
    }
};

// A scene object's arrays. A surface's point fields N.x, N.y and N.z are its
// vertex normals (darkroom/scene/vertex_normals.h), not fields.
ObjectView viewOf(const SceneObject& object);

// What one Embree geometry holds: an object's primitives from
// `firstPrimitive` on (all of them unless the object was split in pieces,
// BvhSettings::piecePrimitives). Pieces are numbered in object order and,
// within an object, in primitive order, so ordering hits by (geometry ID,
// Embree's primitive ID) orders them by (object, primitive) as well.
struct GeometryPiece {
    std::uint32_t object = 0;
    std::size_t firstPrimitive = 0;
};

// The acceleration structure of one scene. Geometry ID g is piece g of
// pieces(): object g itself unless an object was split.
// Vertex and index arrays are shared with Embree, not copied, so their owner
// is kept alive here for as long as the BVH exists.
class SceneBvh {
public:
    // Validates every object (indices in range, field sizes) and throws
    // darkroom::Error naming the object on bad input, since Embree itself
    // would read out of bounds.
    // Without `settings`, bvhSettingsFor() the scene's primitive count.
    SceneBvh(std::shared_ptr<Device> device, std::shared_ptr<const Scene> scene,
             std::optional<BvhSettings> settings = std::nullopt);
    // Objects over arrays `owner` keeps alive (nullptr: the caller does).
    SceneBvh(std::shared_ptr<Device> device, std::vector<ObjectView> objects, std::shared_ptr<const void> owner,
             std::optional<BvhSettings> settings = std::nullopt);
    ~SceneBvh();
    SceneBvh(const SceneBvh&) = delete;
    SceneBvh& operator=(const SceneBvh&) = delete;

    RTCSceneTy* handle() const { return scene_; }
    const std::vector<ObjectView>& objects() const { return objects_; }
    const BvhSettings& settings() const { return settings_; }
    // Indexed by Embree's geometry ID.
    const std::vector<GeometryPiece>& pieces() const { return pieces_; }

private:
    void create(std::optional<BvhSettings> settings);
    void build();
    void attach(const ObjectView& o, std::size_t first, std::size_t count);
    std::shared_ptr<Device> device_;
    std::vector<ObjectView> objects_;
    std::shared_ptr<const void> owner_;
    RTCSceneTy* scene_ = nullptr;
    BvhSettings settings_;
    std::vector<GeometryPiece> pieces_;
};

// Primitives Embree sees for an object (triangles, segments or spheres).
// (SceneObject::primitiveCount() is not exported from the SDK library, so
// plugins cannot call it.)
std::size_t primitiveCountOf(const SceneObject& object);

// Throws darkroom::Error if an object cannot be handed to the ray tracer.
void validateObject(const SceneObject& object, std::size_t index);
void validateObject(const ObjectView& object, std::size_t index);

}  // namespace darkroom::embree
