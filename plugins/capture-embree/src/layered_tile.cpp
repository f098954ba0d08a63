#include "layered_tile.h"

#include "k_nearest_context.h"
#include "nearest_hit_rule.h"
#include "primary_packet.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <limits>

namespace darkroom::embree {

namespace {

// One layer's hits for the 8 lanes of a packet, laid out as PacketHits
// reads them.
struct LayerLanes {
    alignas(32) float t[8];
    alignas(32) unsigned geomID[8];
    alignas(32) unsigned primID[8];
    alignas(32) float u[8];
    alignas(32) float v[8];
    alignas(32) float ng[3][8];

    void set(int k, const Crossing& c) {
        t[k] = c.t;
        geomID[k] = c.geomID;
        primID[k] = c.primID;
        u[k] = c.u;
        v[k] = c.v;
        for (int a = 0; a < 3; ++a) ng[a][k] = c.ng[a];
    }
    void miss(int k) { set(k, Crossing{std::numeric_limits<float>::infinity(), GBufferWriter::kMissID,
                                       GBufferWriter::kMissID, 0.0f, 0.0f, {0.0f, 0.0f, 0.0f}}); }
    // Lane k's committed hit after rtcIntersect8 (or a miss).
    void take(int k, const RTCRayHit8& rh) {
        if (rh.hit.geomID[k] == RTC_INVALID_GEOMETRY_ID) return miss(k);
        set(k, Crossing{rh.ray.tfar[k], rh.hit.geomID[k], rh.hit.primID[k], rh.hit.u[k], rh.hit.v[k],
                        {rh.hit.Ng_x[k], rh.hit.Ng_y[k], rh.hit.Ng_z[k]}});
    }
};

using Packet = PrimaryPacket;

// Packet p loaded with the block at (px, py); the repeated trace moves
// tnear, so the fixed fields are set again each time.
void loadPacket(Packet& p, const PrimaryRays& rays, int px, int py, int x0, int y0, int x1, int y1) {
    setFixedRayFields(p);
    loadPrimaryRays(p, rays, px, py, x0, y0, x1, y1);
}

void traceFiltered(RTCScene scene, KNearestContext& ic, Packet& p, LayerLanes* layers, int count) {
    ic.reset();
    rtcIntersect8(p.valid, scene, &ic.context, &p.rh);
    for (int k = 0; k < 8; ++k)
        for (int j = 0; j < count; ++j) {
            if (p.valid[k] && j < ic.count[k]) layers[j].set(k, ic.hits[k][j]);
            else layers[j].miss(k);
        }
}

// Layer 0 as the one-layer capture traces it; then each further layer from
// the previous one's depth, for the lanes that still hit something.
void traceRepeated(RTCScene scene, NearestHitContext& first, NextCrossingContext& next, Packet& p,
                   LayerLanes* layers, int count) {
    first.reset();
    rtcIntersect8(p.valid, scene, &first.context, &p.rh);
    alignas(32) int valid[8];
    for (int k = 0; k < 8; ++k) {
        layers[0].take(k, p.rh);
        valid[k] = p.valid[k];
    }
    for (int j = 1; j < count; ++j) {
        bool any = false;
        for (int k = 0; k < 8; ++k) {
            const LayerLanes& prev = layers[j - 1];
            if (!valid[k] || prev.geomID[k] == GBufferWriter::kMissID) {
                valid[k] = 0;
                continue;
            }
            next.setPrevious(k, prev.t[k], prev.geomID[k], prev.primID[k]);
            p.rh.ray.tnear[k] = prev.t[k];
            p.rh.ray.tfar[k] = std::numeric_limits<float>::infinity();
            p.rh.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
            p.rh.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
            any = true;
        }
        if (any) rtcIntersect8(valid, scene, &next.context, &p.rh);
        for (int k = 0; k < 8; ++k) {
            if (valid[k]) layers[j].take(k, p.rh);
            else layers[j].miss(k);
        }
    }
}

void writeLayer(const GBufferWriter& writer, const Packet& p, const LayerLanes& l, TileBuffer& tile) {
    const RTCRay8& r = p.rh.ray;
    writer.packet(PacketHits{8, p.valid, l.t, l.geomID, l.primID, l.u, l.v, {l.ng[0], l.ng[1], l.ng[2]},
                             {r.org_x, r.org_y, r.org_z}, {r.dir_x, r.dir_y, r.dir_z}},
                  p.cell, tile);
}

}  // namespace

LayeredTileState::LayeredTileState(const std::vector<GBufferWriter>& writers) {
    tiles.reserve(writers.size());
    for (const auto& w : writers) tiles.push_back(w.tileBuffer());
}

void traceLayeredTile(const SceneBvh& bvh, LayerMethod method, const PrimaryRays& rays,
                      const std::vector<GBufferWriter>& writers, LayeredTileState& state, int width, int height,
                      int x0, int y0) {
    const int count = int(writers.size());
    RTCScene scene = bvh.handle();
    const GeometryPiece* pieces = bvh.pieces().data();
    KNearestContext nearestK(RTC_INTERSECT_CONTEXT_FLAG_COHERENT, count, pieces);
    NearestHitContext first(RTC_INTERSECT_CONTEXT_FLAG_COHERENT);
    NextCrossingContext next(RTC_INTERSECT_CONTEXT_FLAG_COHERENT, pieces);
    Packet p;
    LayerLanes layers[CaptureRequest::kMaxLayers];
    const int x1 = std::min(x0 + TileBuffer::kSize, width), y1 = std::min(y0 + TileBuffer::kSize, height);
    for (int py = y0; py < y1; py += kPacketH)
        for (int px = x0; px < x1; px += kPacketW) {
            loadPacket(p, rays, px, py, x0, y0, x1, y1);
            if (method == LayerMethod::Filter) traceFiltered(scene, nearestK, p, layers, count);
            else traceRepeated(scene, first, next, p, layers, count);
            for (int j = 0; j < count; ++j) writeLayer(writers[std::size_t(j)], p, layers[j], state.tiles[std::size_t(j)]);
        }
    for (int j = 0; j < count; ++j)
        writers[std::size_t(j)].flush(state.tiles[std::size_t(j)], x0, y0, x1 - x0, y1 - y0, width);
}

}  // namespace darkroom::embree
