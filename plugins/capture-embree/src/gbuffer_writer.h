#pragma once
// Turns ray hits into G-buffer pixels: planar depth, interpolated scalars,
// camera-facing normals and ids. Independent of the ray tracer, so the rules
// (what is NaN, how fields are interpolated) live in one place.
#include <darkroom/buffer.h>
#include <darkroom/capture_backend.h>
#include <darkroom/scene.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace darkroom::embree {

// What the tracer reports for one hit. For triangles (u, v) are the weights of
// the second and third vertex; for line segments u runs from the first to the
// second vertex; spheres ignore them.
struct SurfaceHit {
    float t;
    unsigned geomID;
    unsigned primID;
    float u, v;
    float ng[3];  // geometric normal, any length and orientation
};

class GBufferWriter {
public:
    static constexpr std::uint32_t kNoId = 0xFFFFFFFFu;

    // The channels a request produces, in order: Z, the scalars, N.x/N.y/N.z,
    // objectId, primitiveId. Throws darkroom::Error on a duplicate or reserved
    // scalar name.
    static std::vector<ChannelDesc> channels(const CaptureRequest& request);

    // `buffer` must have been allocated with channels(request).
    GBufferWriter(const Scene& scene, const CaptureRequest& request, WritableBuffer& buffer);

    void miss(std::size_t pixel) const {
        z_[pixel] = std::numeric_limits<float>::infinity();
        for (float* s : scalars_) s[pixel] = kNaN;
        if (n_[0]) n_[0][pixel] = n_[1][pixel] = n_[2][pixel] = kNaN;
        if (objectId_) objectId_[pixel] = kNoId;
        if (primitiveId_) primitiveId_[pixel] = kNoId;
    }

    // `dir` is the ray direction (for facing the normal towards the camera).
    // t is planar depth because primary rays are built that way.
    void hit(std::size_t pixel, const SurfaceHit& h, const float dir[3]) const {
        z_[pixel] = h.t;
        const std::size_t nObjects = objects_.size();
        for (std::size_t s = 0; s < scalars_.size(); ++s)
            scalars_[s][pixel] = sample(objects_[h.geomID], fields_[s * nObjects + h.geomID], h);
        if (n_[0]) {
            float nx = h.ng[0], ny = h.ng[1], nz = h.ng[2];
            const float len = std::sqrt(nx * nx + ny * ny + nz * nz);
            // Face the camera: shading passes expect normals on the visible side.
            const float sign = (nx * dir[0] + ny * dir[1] + nz * dir[2]) > 0.0f ? -1.0f : 1.0f;
            const float k = len > 0.0f ? sign / len : kNaN;
            n_[0][pixel] = nx * k;
            n_[1][pixel] = ny * k;
            n_[2][pixel] = nz * k;
        }
        if (objectId_) objectId_[pixel] = h.geomID;
        if (primitiveId_) primitiveId_[pixel] = h.primID;
    }

private:
    static constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

    struct ObjectRef {
        Representation representation;
        const std::uint32_t* indices;
        const std::uint32_t* primitiveCell;  // nullptr: primitive i is cell i
    };
    struct FieldRef {
        const float* values = nullptr;  // nullptr: the object lacks this field
        bool cell = false;
    };

    static float sample(const ObjectRef& o, const FieldRef& f, const SurfaceHit& h) {
        if (!f.values) return kNaN;
        if (f.cell) return f.values[o.primitiveCell ? o.primitiveCell[h.primID] : h.primID];
        switch (o.representation) {
            case Representation::Surface: {
                const std::uint32_t* i = o.indices + 3 * std::size_t(h.primID);
                return (1.0f - h.u - h.v) * f.values[i[0]] + h.u * f.values[i[1]] + h.v * f.values[i[2]];
            }
            case Representation::Lines: {
                const std::uint32_t i = o.indices[h.primID];
                return (1.0f - h.u) * f.values[i] + h.u * f.values[i + 1];
            }
            case Representation::Points: return f.values[h.primID];
        }
        return kNaN;
    }

    std::vector<ObjectRef> objects_;
    std::vector<FieldRef> fields_;  // [scalar * objects + object]
    float* z_ = nullptr;
    std::vector<float*> scalars_;
    float* n_[3] = {nullptr, nullptr, nullptr};
    std::uint32_t* objectId_ = nullptr;
    std::uint32_t* primitiveId_ = nullptr;
};

}  // namespace darkroom::embree
