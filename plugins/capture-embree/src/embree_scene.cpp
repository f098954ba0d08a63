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

std::string objectName(const SceneObject& o, std::size_t index) {
    return "object " + std::to_string(index) + (o.name.empty() ? "" : " ('" + o.name + "')");
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

void validateObject(const SceneObject& o, std::size_t index) {
    if (o.vertices.size() % 4 != 0)
        throw Error("capture: " + objectName(o, index) + " has " + std::to_string(o.vertices.size()) +
                    " vertex floats; expected 4 (x, y, z, radius) per vertex");
    const std::size_t nv = o.vertexCount();
    switch (o.representation) {
        case Representation::Surface:
            if (o.indices.size() % 3 != 0)
                throw Error("capture: " + objectName(o, index) + " has " + std::to_string(o.indices.size()) +
                            " triangle indices; expected a multiple of 3");
            for (std::size_t i = 0; i < o.indices.size(); ++i)
                if (o.indices[i] >= nv)
                    throw Error("capture: " + objectName(o, index) + ": triangle " + std::to_string(i / 3) +
                                " uses vertex " + std::to_string(o.indices[i]) + " but there are only " +
                                std::to_string(nv) + " vertices");
            break;
        case Representation::Lines:
            for (std::size_t i = 0; i < o.indices.size(); ++i)
                if (std::size_t(o.indices[i]) + 1 >= nv)
                    throw Error("capture: " + objectName(o, index) + ": line segment " + std::to_string(i) +
                                " starts at vertex " + std::to_string(o.indices[i]) +
                                " and needs the next one, but there are only " + std::to_string(nv) +
                                " vertices");
            break;
        case Representation::Points: break;
    }
    const std::size_t np = primitiveCountOf(o);
    if (!o.primitiveCell.empty() && o.primitiveCell.size() != np)
        throw Error("capture: " + objectName(o, index) + " maps " + std::to_string(o.primitiveCell.size()) +
                    " primitives to cells but has " + std::to_string(np) + " primitives");
    std::size_t cells = np;
    if (!o.primitiveCell.empty()) {
        cells = 0;
        for (auto c : o.primitiveCell) cells = std::max<std::size_t>(cells, std::size_t(c) + 1);
    }
    for (const auto& f : o.fields) {
        const bool point = f.association == ScalarField::Association::Point;
        if (point && f.values.size() != nv)
            throw Error("capture: " + objectName(o, index) + ": point field '" + f.name + "' has " +
                        std::to_string(f.values.size()) + " values; expected one per vertex (" +
                        std::to_string(nv) + ")");
        if (!point && f.values.size() < cells)
            throw Error("capture: " + objectName(o, index) + ": cell field '" + f.name + "' has " +
                        std::to_string(f.values.size()) + " values; expected at least " +
                        std::to_string(cells) + " (one per cell)");
    }
}

SceneBvh::SceneBvh(std::shared_ptr<Device> device, std::shared_ptr<const Scene> scene)
    : device_(std::move(device)), source_(scene ? std::move(scene) : std::make_shared<const Scene>()) {
    for (std::size_t i = 0; i < source_->objects.size(); ++i) validateObject(source_->objects[i], i);

    RTCDevice dev = device_->handle();
    scene_ = rtcNewScene(dev);
    device_->check("cannot create a scene");
    // A capture renders many views of one scene, so a better BVH pays off.
    rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
    // Ties in depth go to the lowest ids (nearest_hit_rule.h), through the
    // intersection context's filter.
    rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);

    try {
        build();
    } catch (...) {
        rtcReleaseScene(scene_);
        throw;
    }
}

void SceneBvh::build() {
    RTCDevice dev = device_->handle();
    for (std::size_t i = 0; i < source_->objects.size(); ++i) {
        const SceneObject& o = source_->objects[i];
        if (primitiveCountOf(o) == 0) continue;
        RTCGeometry g = nullptr;
        // Vertices are x, y, z, radius records of 16 bytes: Embree reads them
        // in place as FLOAT3 (triangles) or FLOAT4 (curves and spheres). The
        // last record is a full 16 bytes, which is the padding Embree's SSE
        // loads need for shared vertex buffers.
        switch (o.representation) {
            case Representation::Surface:
                g = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_TRIANGLE);
                rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, o.vertices.data(), 0,
                                           16, o.vertexCount());
                rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, o.indices.data(), 0,
                                           12, o.indices.size() / 3);
                break;
            case Representation::Lines:
                // Round curves: cones capped by spheres, i.e. true tubes
                // rather than flat ribbons or tessellated cylinders.
                g = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_ROUND_LINEAR_CURVE);
                rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, o.vertices.data(), 0,
                                           16, o.vertexCount());
                rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT, o.indices.data(), 0, 4,
                                           o.indices.size());
                break;
            case Representation::Points:
                g = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_SPHERE_POINT);
                rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, o.vertices.data(), 0,
                                           16, o.vertexCount());
                break;
        }
        device_->check("cannot set up " + objectName(o, i));
        rtcCommitGeometry(g);
        rtcAttachGeometryByID(scene_, g, unsigned(i));
        rtcReleaseGeometry(g);
        device_->check("cannot add " + objectName(o, i));
    }
    rtcCommitScene(scene_);
    device_->check("cannot build the acceleration structure");
}

SceneBvh::~SceneBvh() {
    if (scene_) rtcReleaseScene(scene_);
}

}  // namespace darkroom::embree
