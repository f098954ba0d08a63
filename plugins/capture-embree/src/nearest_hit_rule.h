#pragma once
// Which hit a ray keeps when several primitives lie at exactly the same
// distance (a ray through an edge two triangles share, the joint of two tube
// segments, coincident spheres): the one with the lowest (object id,
// primitive id). Embree itself keeps whichever candidate its traversal
// presents last or first, which depends on how the BVH was built and so on
// which other primitives the scene holds: without a rule, a scene split over
// MPI ranks (docs/scale-out.md) could not reproduce the single-process
// capture, whose output would also change with unrelated geometry.
//
// Applied by the intersection context's filter (the scene is built with
// RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION): Embree calls it for every
// candidate hit no farther than the current one, nearest first, equal
// distances included, so the filter sees every tied candidate.
#include <embree3/rtcore.h>

#include <limits>

namespace darkroom::embree {

struct NearestHitContext {
    RTCIntersectContext context;  // first member: Embree is handed &context
    // Per packet lane (the ray's id): the hit kept so far.
    float t[8];
    unsigned geomID[8];
    unsigned primID[8];

    explicit NearestHitContext(RTCIntersectContextFlags flags) {
        rtcInitIntersectContext(&context);
        context.flags = flags;
        context.filter = &filter;
        reset();
    }
    // Before each packet.
    void reset() {
        for (int k = 0; k < 8; ++k) {
            t[k] = std::numeric_limits<float>::infinity();
            geomID[k] = primID[k] = RTC_INVALID_GEOMETRY_ID;
        }
    }

    static void filter(const RTCFilterFunctionNArguments* args) {
        auto* self = reinterpret_cast<NearestHitContext*>(args->context);
        for (unsigned i = 0; i < args->N; ++i) {
            if (args->valid[i] != -1) continue;
            const unsigned lane = RTCRayN_id(args->ray, args->N, i) & 7u;
            const float t = RTCRayN_tfar(args->ray, args->N, i);
            const unsigned g = RTCHitN_geomID(args->hit, args->N, i), p = RTCHitN_primID(args->hit, args->N, i);
            // Candidates are never farther than the hit kept (Embree tests
            // t <= tfar); at the same distance the lower ids win.
            const bool better = t < self->t[lane] ||
                                (t == self->t[lane] && (g < self->geomID[lane] ||
                                                        (g == self->geomID[lane] && p <= self->primID[lane])));
            if (!better) {
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
