#pragma once
// The part of writing a 4x2 packet into a tile buffer that is the same for
// every lane: depth, normals, ids and the NaN of missed scalars, a row of 4
// lanes at a time with the best SIMD instructions of the CPU.
#include "gbuffer_writer.h"

#include <cstdint>

namespace darkroom::embree {

struct PacketRowTargets {
    float* z;                          // tile cell of lane 0
    float* normal[3];                  // or nullptr
    float* const* scalars;             // `scalarCount` planes filled with NaN (hits are written afterwards)
    int scalarCount;
    std::uint32_t* objectId;           // or nullptr
    std::uint32_t* primitiveId;        // or nullptr
    int rowStride;                     // floats from one tile row to the next
};

// Lanes 0-3 are the first row, 4-7 the second. Depth is Embree's t (the
// caller refines sphere hits), normals face the ray (GBufferWriter's
// facingNormal: the same float operations, the same bits); misses get +inf
// depth, NaN normals and ~0u ids.
void writePacketRows(const PacketHits& p, const PacketRowTargets& t);

// Copies h rows of w 4-byte values (rows srcStride / dstStride values apart)
// into a plane. Whole 64-byte-aligned rows go around the caches (streaming
// stores): a G-buffer is written once, and reading each destination line
// first would double the memory traffic. Call finishRows() before the planes
// are read by another thread.
void copyRows(const void* src, int srcStride, void* dst, std::size_t dstStride, int w, int h);
void finishRows();

}  // namespace darkroom::embree
