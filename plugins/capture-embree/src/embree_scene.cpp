#include "embree_scene.h"

#include <darkroom/error.h>
#include <embree3/rtcore.h>

#include <algorithm>
#include <string>

namespace darkroom::embree {

namespace {

const char* errorName(RTCError e) {
    switch (e) {
        case RTC_ERROR_NONE: return "no error";
        case RTC_ERROR_UNKNOWN: return "unknown error";
        case RTC_ERROR_INVALID_ARGUMENT: return "invalid argument";
        case RTC_ERROR_INVALID_OPERATION: return "invalid operation";
        case RTC_ERROR_OUT_OF_MEMORY: return "out of memory";
        case RTC_ERROR_UNSUPPORTED_CPU: return "unsupported CPU";
        case RTC_ERROR_CANCELLED: return "cancelled";
    }
    return "error";
}

std::string objectName(const std::string& name, std::size_t index) {
    return "object " + std::to_string(index) + (name.empty() ? "" : " ('" + name + "')");
}

}  // namespace

Device::Device() {
    device_ = rtcNewDevice(nullptr);
    if (!device_)
        throw Error(std::string("embree: cannot create a device: ") + errorName(rtcGetDeviceError(nullptr)));
}

Device::~Device() { rtcReleaseDevice(device_); }

void Device::check(const std::string& what) const {
    const RTCError e = rtcGetDeviceError(device_);
    if (e != RTC_ERROR_NONE) throw Error("embree: " + what + ": " + errorName(e));
}

std::size_t primitiveCountOf(const SceneObject& o) {
    switch (o.representation) {
        case Representation::Surface: return o.indices.size() / 3;
        case Representation::Lines: return o.indices.size();
        case Representation::Points: return o.vertexCount();
    }
    return 0;
}

ObjectView viewOf(const SceneObject& o) {
    ObjectView v;
    v.name = o.name;
    v.representation = o.representation;
    v.vertices = o.vertices.data();
    v.vertexStride = 16;
    v.vertexCount = o.vertexCount();
    v.indices = o.indices.data();
    v.primitiveCount = primitiveCountOf(o);
    v.primitiveCell = o.primitiveCell.empty() ? nullptr : o.primitiveCell.data();
    // The scene library's convention for vertex normals: all three point
    // fields, one value per vertex, on a surface; anything else stays a field.
    static const char* const kNormalFields[3] = {"N.x", "N.y", "N.z"};
    const ScalarField* normal[3] = {nullptr, nullptr, nullptr};
    for (const auto& f : o.fields)
        for (int a = 0; a < 3; ++a)
            if (f.name == kNormalFields[a] && f.association == ScalarField::Association::Point &&
                f.values.size() == v.vertexCount)
                normal[a] = &f;
    const bool normals = o.representation == Representation::Surface && normal[0] && normal[1] && normal[2];
    for (int a = 0; normals && a < 3; ++a) v.normals[a] = normal[a]->values.data();
    for (const auto& f : o.fields) {
        if (normals && (&f == normal[0] || &f == normal[1] || &f == normal[2])) continue;
        v.fields.push_back({f.name, f.values.data(), f.values.size(), f.association == ScalarField::Association::Cell});
    }
    return v;
}

void validateObject(const SceneObject& o, std::size_t index) {
    if (o.vertices.size() % 4 != 0)
        throw Error("capture: " + objectName(o.name, index) + " has " + std::to_string(o.vertices.size()) +
                    " vertex floats; expected 4 (x, y, z, radius) per vertex");
    if (!o.primitiveCell.empty() && o.primitiveCell.size() != primitiveCountOf(o))
        throw Error("capture: " + objectName(o.name, index) + " maps " + std::to_string(o.primitiveCell.size()) +
                    " primitives to cells but has " + std::to_string(primitiveCountOf(o)) + " primitives");
    if (o.representation == Representation::Surface && o.indices.size() % 3 != 0)
        throw Error("capture: " + objectName(o.name, index) + " has " + std::to_string(o.indices.size()) +
                    " triangle indices; expected a multiple of 3");
    validateObject(viewOf(o), index);
}

void validateObject(const ObjectView& o, std::size_t index) {
    const std::size_t nv = o.vertexCount;
    const std::size_t minStride = o.representation == Representation::Surface ? 12 : 16;
    if (o.vertexStride < minStride || o.vertexStride % 4 != 0)
        throw Error("capture: " + objectName(o.name, index) + " has vertices " + std::to_string(o.vertexStride) +
                    " bytes apart; expected a multiple of 4 of at least " + std::to_string(minStride) +
                    (minStride == 16 ? " (x, y, z, radius)" : " (x, y, z)"));
    if (nv > 0 && !o.vertices) throw Error("capture: " + objectName(o.name, index) + " has no vertex array");
    if (o.primitiveCount > 0 && o.representation != Representation::Points && !o.indices)
        throw Error("capture: " + objectName(o.name, index) + " has no index array");
    const std::size_t np = o.representation == Representation::Points ? nv : o.primitiveCount;
    switch (o.representation) {
        case Representation::Surface:
            for (std::size_t i = 0; i < 3 * np; ++i)
                if (o.indices[i] >= nv)
                    throw Error("capture: " + objectName(o.name, index) + ": triangle " + std::to_string(i / 3) +
                                " uses vertex " + std::to_string(o.indices[i]) + " but there are only " +
                                std::to_string(nv) + " vertices");
            break;
        case Representation::Lines:
            for (std::size_t i = 0; i < np; ++i)
                if (std::size_t(o.indices[i]) + 1 >= nv)
                    throw Error("capture: " + objectName(o.name, index) + ": line segment " + std::to_string(i) +
                                " starts at vertex " + std::to_string(o.indices[i]) +
                                " and needs the next one, but there are only " + std::to_string(nv) +
                                " vertices");
            break;
        case Representation::Points: break;
    }
    std::size_t cells = np;
    if (o.primitiveCell) {
        cells = 0;
        for (std::size_t i = 0; i < np; ++i) cells = std::max<std::size_t>(cells, std::size_t(o.primitiveCell[i]) + 1);
    }
    for (const auto& f : o.fields) {
        if (!f.cell && f.count != nv)
            throw Error("capture: " + objectName(o.name, index) + ": point field '" + f.name + "' has " +
                        std::to_string(f.count) + " values; expected one per vertex (" + std::to_string(nv) + ")");
        if (f.cell && f.count < cells)
            throw Error("capture: " + objectName(o.name, index) + ": cell field '" + f.name + "' has " +
                        std::to_string(f.count) + " values; expected at least " + std::to_string(cells) +
                        " (one per cell)");
        if (f.count > 0 && !f.values)
            throw Error("capture: " + objectName(o.name, index) + ": field '" + f.name + "' has no values");
    }
}

SceneBvh::SceneBvh(std::shared_ptr<Device> device, std::shared_ptr<const Scene> scene,
                   std::optional<BvhSettings> settings)
    : device_(std::move(device)) {
    if (!scene) scene = std::make_shared<const Scene>();
    for (std::size_t i = 0; i < scene->objects.size(); ++i) validateObject(scene->objects[i], i);
    for (const auto& o : scene->objects) objects_.push_back(viewOf(o));
    owner_ = std::move(scene);
    create(settings);
}

SceneBvh::SceneBvh(std::shared_ptr<Device> device, std::vector<ObjectView> objects, std::shared_ptr<const void> owner,
                   std::optional<BvhSettings> settings)
    : device_(std::move(device)), objects_(std::move(objects)), owner_(std::move(owner)) {
    for (std::size_t i = 0; i < objects_.size(); ++i) validateObject(objects_[i], i);
    create(settings);
}

void SceneBvh::create(std::optional<BvhSettings> settings) {
    if (!settings) {
        std::size_t primitives = 0;
        for (const auto& o : objects_) primitives += o.primitiveCount;
        settings = bvhSettingsFor(primitives);
    }
    settings_ = *settings;
    RTCDevice dev = device_->handle();
    scene_ = rtcNewScene(dev);
    device_->check("cannot create a scene");
    rtcSetSceneBuildQuality(scene_, settings_.quality == BvhSettings::Quality::High     ? RTC_BUILD_QUALITY_HIGH
                                    : settings_.quality == BvhSettings::Quality::Medium ? RTC_BUILD_QUALITY_MEDIUM
                                                                                        : RTC_BUILD_QUALITY_LOW);
    // Watertight ray-triangle tests: without it a ray can slip between two
    // triangles sharing an edge and hit the far side (1-3 crack pixels per
    // 768^2 view of the demo isosurface; tests/test_watertight.cpp). Costs
    // about 7 % of capture time (bench_capture, load 8-9 on 2 cores).
    // Ties in depth go to the lowest ids (nearest_hit_rule.h), through the
    // intersection context's filter.
    rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION |
                                 (settings_.compact ? RTC_SCENE_FLAG_COMPACT : RTC_SCENE_FLAG_NONE));

    try {
        build();
    } catch (...) {
        rtcReleaseScene(scene_);
        scene_ = nullptr;
        throw;
    }
}

void SceneBvh::build() {
    for (std::size_t i = 0; i < objects_.size(); ++i) {
        const ObjectView& o = objects_[i];
        const std::size_t piece = settings_.piecePrimitives;
        const bool split = o.representation == Representation::Surface && piece > 0 && o.primitiveCount > piece;
        std::size_t first = 0;
        do {
            const std::size_t count = split ? std::min(piece, o.primitiveCount - first) : o.primitiveCount;
            pieces_.push_back({std::uint32_t(i), first});
            attach(o, first, count);
            first += count;
        } while (first < o.primitiveCount);
    }
    rtcCommitScene(scene_);
    device_->check("cannot build the acceleration structure");
}

// Primitives [first, first + count) of `o` as the geometry of the last
// piece (an object without primitives keeps its ID but gets no geometry).
void SceneBvh::attach(const ObjectView& o, std::size_t first, std::size_t count) {
    if (count == 0 || o.vertexCount == 0) return;
    const unsigned id = unsigned(pieces_.size() - 1);
    RTCDevice dev = device_->handle();
    RTCGeometry g = nullptr;
    // Vertices are x, y, z(, radius) records: Embree reads them in place
    // as FLOAT3 (triangles) or FLOAT4 (curves and spheres). Scene objects
    // use 16-byte records, so the last one is the padding Embree's SSE
    // loads need; 12-byte records (in situ triangles) must be followed
    // by 4 readable bytes, which darkroom/insitu.h asks of its callers.
    // A piece shares all the vertices and its run of the indices.
    switch (o.representation) {
        case Representation::Surface:
            g = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_TRIANGLE);
            rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, o.vertices, 0, o.vertexStride,
                                       o.vertexCount);
            rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, o.indices, 12 * first, 12,
                                       count);
            break;
        case Representation::Lines:
            // Round curves: cones capped by spheres, i.e. true tubes
            // rather than flat ribbons or tessellated cylinders.
            g = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_ROUND_LINEAR_CURVE);
            rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, o.vertices, 0, o.vertexStride,
                                       o.vertexCount);
            rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT, o.indices, 0, 4, count);
            break;
        case Representation::Points:
            g = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_SPHERE_POINT);
            rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, o.vertices, 0, o.vertexStride,
                                       o.vertexCount);
            break;
    }
    const std::string name = objectName(o.name, pieces_.back().object);
    device_->check("cannot set up " + name);
    // Low: each geometry gets its own BVH from Embree's Morton builder
    // (under a two-level scene), several times faster to build than SAH.
    if (settings_.quality == BvhSettings::Quality::Low) rtcSetGeometryBuildQuality(g, RTC_BUILD_QUALITY_LOW);
    rtcCommitGeometry(g);
    rtcAttachGeometryByID(scene_, g, id);
    rtcReleaseGeometry(g);
    device_->check("cannot add " + name);
}

SceneBvh::~SceneBvh() {
    if (scene_) rtcReleaseScene(scene_);
}

}  // namespace darkroom::embree
