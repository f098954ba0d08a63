#pragma once
// What counts as one surface crossing when a capture keeps the K nearest
// (CaptureRequest::layers, darkroom/layers.h), shared by both ways of
// finding them (layered_tile.cpp) so that they give the same layers.
//
// Crossings are ordered by (t, object id, primitive id): nearest first, ties
// to the lowest ids, as nearest_hit_rule.h orders layer 0. A ray through an
// edge or vertex that triangles of one object share hits each of them at
// (nearly) the same t: that is one crossing, not several, or a closed
// surface would show its front twice. So two hits of the same object whose
// depths agree to kSameCrossing (relative; a few hundred float ulps, far
// below any real distance between two sheets of one surface) are the same
// crossing, and the one with the lower key stands for it. Embree may also
// report a primitive twice (spatial splits); that is the same rule. A big
// surface may be several Embree geometries (GeometryPiece): the rule asks
// for the same object, not the same geometry, and the pieces' IDs keep the
// order of (object, primitive).
#include "embree_scene.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace darkroom::embree {

struct Crossing {
    float t;
    unsigned geomID;
    unsigned primID;
    float u, v;
    float ng[3];
};

inline constexpr float kSameCrossing = 1e-5f;

// Whether a comes before b.
inline bool before(float ta, unsigned ga, unsigned pa, float tb, unsigned gb, unsigned pb) {
    return ta < tb || (ta == tb && (ga < gb || (ga == gb && pa < pb)));
}
inline bool before(const Crossing& a, const Crossing& b) {
    return before(a.t, a.geomID, a.primID, b.t, b.geomID, b.primID);
}

// `objectA` and `objectB`: the objects of the two hits' geometries.
inline bool sameCrossing(float ta, unsigned objectA, float tb, unsigned objectB) {
    return objectA == objectB && std::abs(ta - tb) <= kSameCrossing * std::max(std::abs(ta), std::abs(tb));
}

// The object of geometry g: piece g's, or g itself without pieces.
inline unsigned objectOf(const GeometryPiece* pieces, unsigned g) { return pieces ? pieces[g].object : g; }

}  // namespace darkroom::embree
