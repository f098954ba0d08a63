#pragma once
// Turns ray hits into G-buffer pixels: planar depth, interpolated scalars,
// camera-facing normals and ids. Independent of the ray tracer, so the rules
// (what is NaN, how fields are interpolated) live in one place.
#include "embree_scene.h"

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
    GBufferWriter(const std::vector<ObjectView>& objects, const CaptureRequest& request, WritableBuffer& buffer);

    // Starts loading what hit() will read for this primitive, so that the
    // cache misses of the 8 lanes of a packet overlap instead of queueing.
    void prefetch(const SurfaceHit& h) const {
        const ObjectRef& o = objects_[h.geomID];
        if (scalars_.empty() && o.representation != Representation::Points) return;  // nothing to read
        if (o.representation == Representation::Surface) __builtin_prefetch(o.indices + 3 * std::size_t(h.primID));
        else if (o.representation == Representation::Lines) __builtin_prefetch(o.indices + h.primID);
        else __builtin_prefetch(o.vertex(h.primID));
    }

    void miss(std::size_t pixel) const {
        z_[pixel] = std::numeric_limits<float>::infinity();
        for (float* s : scalars_) s[pixel] = kNaN;
        if (n_[0]) n_[0][pixel] = n_[1][pixel] = n_[2][pixel] = kNaN;
        if (objectId_) objectId_[pixel] = kNoId;
        if (primitiveId_) primitiveId_[pixel] = kNoId;
    }

    // `org` and `dir` are the ray's (dir for facing the normal towards the
    // camera). t is planar depth because primary rays are built that way.
    void hit(std::size_t pixel, const SurfaceHit& h, const float org[3], const float dir[3]) const {
        const ObjectRef& o = objects_[h.geomID];
        z_[pixel] = refineDepth(o, h, org, dir);
        const std::size_t nObjects = objects_.size();
        for (std::size_t s = 0; s < scalars_.size(); ++s)
            scalars_[s][pixel] = sample(o, fields_[s * nObjects + h.geomID], h);
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
        const float* vertices;  // x, y, z, radius records
        std::size_t stride;     // bytes between records
        const std::uint32_t* indices;
        const std::uint32_t* primitiveCell;  // nullptr: primitive i is cell i
        const float* vertex(unsigned i) const {
            return reinterpret_cast<const float*>(reinterpret_cast<const char*>(vertices) + i * stride);
        }
    };
    struct FieldRef {
        const float* values = nullptr;  // nullptr: the object lacks this field
        bool cell = false;
    };

    // Embree's single-precision t is within a few ulps of the true distance
    // for triangles (kept: recomputing it costs two dependent cache misses
    // per hit, measured at 10-25% of a depth-only capture). Sphere hits are
    // recomputed in double from the centre (one load, next to the point's
    // scalar) because Embree's sphere t is less accurate. A refinement that
    // disagrees wildly with Embree is discarded.
    static float refineDepth(const ObjectRef& o, const SurfaceHit& h, const float org[3], const float dir[3]) {
        if (o.representation != Representation::Points) return h.t;
        double t = h.t;
        const double ox = org[0], oy = org[1], oz = org[2], dx = dir[0], dy = dir[1], dz = dir[2];
        {
            const float* c = o.vertex(h.primID);
            const double px = ox - c[0], py = oy - c[1], pz = oz - c[2], r = c[3];
            const double qa = dx * dx + dy * dy + dz * dz, qb = px * dx + py * dy + pz * dz;
            const double disc = qb * qb - qa * (px * px + py * py + pz * pz - r * r);
            // Near side when the camera is outside the sphere, far side from inside.
            if (disc >= 0.0 && qa > 0.0) {
                const double root = std::sqrt(disc);
                const double tNear = (-qb - root) / qa;
                t = tNear > 0.0 ? tNear : (-qb + root) / qa;
            }
        }
        const double embree = h.t;
        if (!(std::abs(t - embree) <= 1e-3 * embree)) t = embree;
        return float(t);
    }

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
