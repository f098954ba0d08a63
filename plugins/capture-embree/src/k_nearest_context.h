#pragma once
// The K nearest crossings of each ray of a packet in one traversal: an
// intersection-context filter that records every candidate hit Embree
// presents (in traversal order, not depth order) into a short sorted list
// per lane and rejects it, so that traversal goes on behind it. Once a
// lane's list is full, the candidate that becomes its K-th entry is
// accepted instead: Embree then shrinks the ray's tfar to it and culls
// everything farther (a filter can only move tfar by accepting a hit).
// Rejecting every other candidate keeps the nearer entries from cutting the
// ray short. Which hits are one crossing: crossing_rule.h.
#include "crossing_rule.h"

#include <darkroom/capture_backend.h>
#include <embree3/rtcore.h>

#include <limits>

namespace darkroom::embree {

struct KNearestContext {
    RTCIntersectContext context;  // first member: Embree is handed &context
    int k;
    const GeometryPiece* pieces;  // SceneBvh::pieces(), or nullptr: geometry i is object i
    int count[8];
    Crossing hits[8][CaptureRequest::kMaxLayers];  // per lane, nearest first

    KNearestContext(RTCIntersectContextFlags flags, int layers, const GeometryPiece* pieces)
        : k(layers), pieces(pieces) {
        rtcInitIntersectContext(&context);
        context.flags = flags;
        context.filter = &filter;
        reset();
    }
    void reset() {
        for (int& c : count) c = 0;
    }

    // Adds c to lane `lane`'s list; returns whether it is now the last entry
    // of a full list (the hit to accept).
    bool insert(int lane, const Crossing& c) {
        Crossing* list = hits[lane];
        int& n = count[lane];
        for (int i = 0; i < n; ++i) {
            if (!sameCrossing(list[i].t, objectOf(pieces, list[i].geomID), c.t, objectOf(pieces, c.geomID))) continue;
            if (!before(c, list[i])) return false;  // the crossing is already kept by a lower key
            for (int j = i; j + 1 < n; ++j) list[j] = list[j + 1];  // c replaces it below
            --n;
            break;
        }
        if (n == k && !before(c, list[k - 1])) return false;
        int at = n < k ? n : k - 1;
        for (; at > 0 && before(c, list[at - 1]); --at) list[at] = list[at - 1];
        list[at] = c;
        if (n < k) ++n;
        return n == k && at == k - 1;
    }

    static void filter(const RTCFilterFunctionNArguments* args) {
        auto* self = reinterpret_cast<KNearestContext*>(args->context);
        for (unsigned i = 0; i < args->N; ++i) {
            if (args->valid[i] != -1) continue;
            const int lane = int(RTCRayN_id(args->ray, args->N, i) & 7u);
            const Crossing c{RTCRayN_tfar(args->ray, args->N, i),
                             RTCHitN_geomID(args->hit, args->N, i),
                             RTCHitN_primID(args->hit, args->N, i),
                             RTCHitN_u(args->hit, args->N, i),
                             RTCHitN_v(args->hit, args->N, i),
                             {RTCHitN_Ng_x(args->hit, args->N, i), RTCHitN_Ng_y(args->hit, args->N, i),
                              RTCHitN_Ng_z(args->hit, args->N, i)}};
            if (!self->insert(lane, c)) args->valid[i] = 0;
        }
    }
};

// The repeated-tracing alternative: after the nearest crossing `prev` of a
// lane is known, the ray is traced again from prev's depth and this filter
// keeps the nearest candidate after it (crossing_rule.h's order), skipping
// prev itself and every hit that is the same crossing as prev.
struct NextCrossingContext {
    RTCIntersectContext context;
    const GeometryPiece* pieces;
    float prevT[8], t[8];
    unsigned prevGeom[8], prevPrim[8], geomID[8], primID[8];

    NextCrossingContext(RTCIntersectContextFlags flags, const GeometryPiece* pieces) : pieces(pieces) {
        rtcInitIntersectContext(&context);
        context.flags = flags;
        context.filter = &filter;
    }
    // Before tracing a lane again after the crossing (t, g, p).
    void setPrevious(int lane, float pt, unsigned g, unsigned p) {
        prevT[lane] = pt;
        prevGeom[lane] = g;
        prevPrim[lane] = p;
        t[lane] = std::numeric_limits<float>::infinity();
        geomID[lane] = primID[lane] = RTC_INVALID_GEOMETRY_ID;
    }

    static void filter(const RTCFilterFunctionNArguments* args) {
        auto* self = reinterpret_cast<NextCrossingContext*>(args->context);
        for (unsigned i = 0; i < args->N; ++i) {
            if (args->valid[i] != -1) continue;
            const unsigned lane = RTCRayN_id(args->ray, args->N, i) & 7u;
            const float t = RTCRayN_tfar(args->ray, args->N, i);
            const unsigned g = RTCHitN_geomID(args->hit, args->N, i), p = RTCHitN_primID(args->hit, args->N, i);
            const bool next = before(self->prevT[lane], self->prevGeom[lane], self->prevPrim[lane], t, g, p) &&
                              !sameCrossing(self->prevT[lane], objectOf(self->pieces, self->prevGeom[lane]), t,
                                            objectOf(self->pieces, g));
            if (!next || !before(t, g, p, self->t[lane], self->geomID[lane], self->primID[lane])) {
                args->valid[i] = 0;
                continue;
            }
            self->t[lane] = t;
            self->geomID[lane] = g;
            self->primID[lane] = p;
        }
    }
};

}  // namespace darkroom::embree
