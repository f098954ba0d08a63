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

// The lanes of one ray packet as the tracer reports them (structure of
// arrays, e.g. views into Embree's RTCRayHit8), `lanes` long.
struct PacketHits {
    int lanes;
    const int* valid;       // -1: lane in use
    const float* t;
    const unsigned* geomID;  // kMissID: no hit
    const unsigned* primID;
    const float *u, *v;
    const float* ng[3];
    const float* org[3];
    const float* dir[3];
};

// The G-buffer of one tile (at most kSize x kSize pixels, row-major with
// rows kSize apart), filled packet by packet and copied into the planes row
// by row when the tile is done: the packets' scattered 2x4 blocks land in a
// few cache lines, and the planes get whole rows.
class TileBuffer {
public:
    static constexpr int kSize = 16;
    explicit TileBuffer(std::size_t floatChannels, bool objectId, bool primitiveId)
        : floats_(floatChannels * kSize * kSize), objectId_(objectId ? kSize * kSize : 0),
          primitiveId_(primitiveId ? kSize * kSize : 0) {}
    float* channel(std::size_t c) { return floats_.data() + c * kSize * kSize; }
    const float* channel(std::size_t c) const { return floats_.data() + c * kSize * kSize; }
    std::uint32_t* objectId() { return objectId_.data(); }
    std::uint32_t* primitiveId() { return primitiveId_.data(); }
    const std::uint32_t* objectId() const { return objectId_.data(); }
    const std::uint32_t* primitiveId() const { return primitiveId_.data(); }

private:
    std::vector<float> floats_;
    std::vector<std::uint32_t> objectId_, primitiveId_;
};

class GBufferWriter {
public:
    static constexpr std::uint32_t kNoId = 0xFFFFFFFFu;

    // The channels a request produces, in order: Z, the scalars, N.x/N.y/N.z,
    // objectId, primitiveId; then the same for each further layer under
    // darkroom/layers.h's names (layer1.Z, ...). Throws darkroom::Error on a
    // duplicate or reserved scalar name or a layer count out of range.
    static std::vector<ChannelDesc> channels(const CaptureRequest& request);

    // `buffer` must have been allocated with channels(request); the writer
    // fills layer `layer`'s channels. Hits name their geometry: piece g of
    // `pieces` (SceneBvh::pieces()); empty: geometry i is object i.
    GBufferWriter(const std::vector<ObjectView>& objects, const std::vector<GeometryPiece>& pieces,
                  const CaptureRequest& request, WritableBuffer& buffer, int layer = 0);

    static constexpr unsigned kMissID = 0xFFFFFFFFu;  // RTC_INVALID_GEOMETRY_ID

    // A tile buffer for this writer's channels.
    TileBuffer tileBuffer() const {
        return TileBuffer(1 + scalars_.size() + (n_[0] ? 3 : 0), objectId_ != nullptr, primitiveId_ != nullptr);
    }

    // Lane k of a 4x2 packet `p` is pixel cell[k] of `tile` (y *
    // TileBuffer::kSize + x; lanes 0-3 the first row, 4-7 the second): the
    // same values hit() and miss() give.
    void packet(const PacketHits& p, const int* cell, TileBuffer& tile) const;

    // Copies the w x h tile into the planes at (x0, y0).
    void flush(const TileBuffer& tile, int x0, int y0, int w, int h, int imageWidth) const;

    // Starts loading what hit() will read for this primitive, so that the
    // cache misses of the 8 lanes of a packet overlap instead of queueing.
    void prefetch(const SurfaceHit& h) const {
        const ObjectRef& o = objects_[h.geomID];
        if (scalars_.empty() && o.representation != Representation::Points && !smooth(o)) return;  // nothing to read
        if (o.representation == Representation::Surface) __builtin_prefetch(o.indices + 3 * std::size_t(h.primID));
        else if (o.representation == Representation::Lines) __builtin_prefetch(o.indices + h.primID);
        else __builtin_prefetch(o.vertex(h.primID));
    }

    // After prefetch(): starts loading the field values hit() will interpolate
    // (the primitive's indices have arrived by now).
    void prefetchFields(const SurfaceHit& h) const {
        const ObjectRef& o = objects_[h.geomID];
        const std::size_t nObjects = objects_.size();
        if (smooth(o)) {
            const std::uint32_t* i = o.indices + 3 * std::size_t(h.primID);
            for (const float* n : o.normals)
                for (int k = 0; k < 3; ++k) __builtin_prefetch(n + i[k]);
        }
        for (std::size_t s = 0; s < scalars_.size(); ++s) {
            const FieldRef& f = fields_[s * nObjects + h.geomID];
            if (!f.values) continue;
            if (f.cell) {
                __builtin_prefetch(f.values + (o.primitiveCell ? o.primitiveCell[h.primID] : h.primID));
            } else if (o.representation == Representation::Surface) {
                const std::uint32_t* i = o.indices + 3 * std::size_t(h.primID);
                __builtin_prefetch(f.values + i[0]);
                __builtin_prefetch(f.values + i[1]);
                __builtin_prefetch(f.values + i[2]);
            } else if (o.representation == Representation::Lines) {
                __builtin_prefetch(f.values + o.indices[h.primID]);
            }
        }
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
            float n[3];
            facingNormal(h.ng[0], h.ng[1], h.ng[2], dir[0], dir[1], dir[2], n);
            if (smooth(o)) smoothNormal(o, h, dir, n);
            n_[0][pixel] = n[0];
            n_[1][pixel] = n[1];
            n_[2][pixel] = n[2];
        }
        if (objectId_) objectId_[pixel] = o.object;
        if (primitiveId_) primitiveId_[pixel] = o.firstPrimitive + h.primID;
    }

private:
    static constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

    // The unit geometric normal on the side facing the ray (shading passes
    // expect normals on the visible side); NaN for a zero normal.
    static void facingNormal(float nx, float ny, float nz, float dx, float dy, float dz, float n[3]) {
        const float len = std::sqrt(nx * nx + ny * ny + nz * nz);
        const float sign = (nx * dx + ny * dy + nz * dz) > 0.0f ? -1.0f : 1.0f;
        const float k = len > 0.0f ? sign / len : kNaN;
        n[0] = nx * k;
        n[1] = ny * k;
        n[2] = nz * k;
    }

    // One geometry (an object, or a piece of one): its arrays start at its
    // first primitive, so that Embree's primitive ID indexes them directly.
    struct ObjectRef {
        Representation representation;
        const float* vertices;  // x, y, z, radius records
        std::size_t stride;     // bytes between records
        const std::uint32_t* indices;
        const std::uint32_t* primitiveCell;  // nullptr: primitive i is cell i
        const float* normals[3];             // vertex normals (surfaces), or nullptr
        std::uint32_t object;                // the ids the G-buffer stores
        std::uint32_t firstPrimitive;
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

    // Whether normals are stored and this object's come from its vertices.
    bool smooth(const ObjectRef& o) const { return n_[0] && o.normals[0]; }

    // Replaces `n`, the unit geometric normal facing the ray, with the vertex
    // normals interpolated at the hit (shading_normal.cpp); leaves it where
    // they cancel out.
    static void smoothNormal(const ObjectRef& o, const SurfaceHit& h, const float dir[3], float n[3]);

    // The ids writePacketRows stored (Embree's) made the object's own.
    void pieceIds(const PacketHits& p, const int* cell, TileBuffer& tile) const;

    std::vector<ObjectRef> objects_;  // per geometry
    bool pieces_ = false;             // some object is split: geometry IDs are not object ids
    bool hasPoints_ = false;  // sphere hits have their depth refined
    bool hasSmooth_ = false;  // some object's normals are interpolated (and normals are stored)
    std::vector<FieldRef> fields_;  // [scalar * geometries + geometry]
    float* z_ = nullptr;
    std::vector<float*> scalars_;
    float* n_[3] = {nullptr, nullptr, nullptr};
    std::uint32_t* objectId_ = nullptr;
    std::uint32_t* primitiveId_ = nullptr;
};

}  // namespace darkroom::embree
