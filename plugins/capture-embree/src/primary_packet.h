#pragma once
// A packet of 8 primary rays over a 4x2 block of a tile, as both captures
// trace them (the one-layer loop in embree_backend.cpp and the layered one
// in layered_tile.cpp), so that layer 0 of a layered capture is traced
// exactly as a one-layer capture traces its nearest hits.
#include "gbuffer_writer.h"
#include "primary_rays.h"

#include <embree3/rtcore.h>

#include <limits>

namespace darkroom::embree {

constexpr int kPacketW = 4;
constexpr int kPacketH = 2;
static_assert(kPacketW * kPacketH == 8);

struct PrimaryPacket {
    alignas(32) RTCRayHit8 rh;
    alignas(32) int valid[8];
    int cell[8];  // each lane's cell in the tile buffer
};

// The ray fields Embree never writes: set once for a packet that is reused
// (and again after anything, such as a repeated trace, changes tnear).
inline void setFixedRayFields(PrimaryPacket& p) {
    for (int k = 0; k < 8; ++k) {
        p.rh.ray.tnear[k] = 0.0f;
        p.rh.ray.time[k] = 0.0f;
        p.rh.ray.mask[k] = 0xFFFFFFFFu;
        p.rh.ray.id[k] = unsigned(k);
        p.rh.ray.flags[k] = 0;
    }
}

// The primary rays of the 4x2 block at (px, py) of the tile whose corner is
// (x0, y0); lanes outside [x0, x1) x [y0, y1) are switched off, so edge
// tiles keep the packet shape.
inline void loadPrimaryRays(PrimaryPacket& p, const PrimaryRays& rays, int px, int py, int x0, int y0, int x1,
                            int y1) {
    RTCRayHit8& rh = p.rh;
    for (int k = 0; k < 8; ++k) {
        const int x = px + k % kPacketW, y = py + k / kPacketW;
        p.valid[k] = (x < x1 && y < y1) ? -1 : 0;
        p.cell[k] = (y - y0) * TileBuffer::kSize + (x - x0);
        float o[3] = {0, 0, 0}, d[3] = {0, 0, 1};
        if (p.valid[k]) rays(x, y, o, d);
        rh.ray.org_x[k] = o[0];
        rh.ray.org_y[k] = o[1];
        rh.ray.org_z[k] = o[2];
        rh.ray.dir_x[k] = d[0];
        rh.ray.dir_y[k] = d[1];
        rh.ray.dir_z[k] = d[2];
        rh.ray.tfar[k] = std::numeric_limits<float>::infinity();
        rh.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
        rh.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
    }
}

}  // namespace darkroom::embree
