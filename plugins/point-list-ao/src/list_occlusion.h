#pragma once
// The occlusion of one receiver by every primitive of the grid that can
// reach it: each primitive's closed form (closed_forms.h), combined as
// independent occluders, AO = product of (1 - F_i) — exact for primitives
// whose silhouettes do not overlap as seen from the receiver, and the
// expected value for occluders scattered at random (a particle cloud).
#include "primitive_grid.h"

namespace darkroom::listao {

class ListOcclusion {
public:
    explicit ListOcclusion(const PrimitiveGrid& grid) : grid_(grid) {}

    // Unoccluded fraction in [0, 1] at view-space point p with unit normal n,
    // counting occluders nearer than R.
    float visibility(V3f p, V3f n, float R) const;

    // When p lies on a primitive's surface (within `tolerance`), its outward
    // normal there; false otherwise. For receivers on spheres and lines when
    // the G-buffer stores no normals: the list knows them exactly.
    bool surfaceNormal(V3f p, float tolerance, V3f& n) const;

private:
    const PrimitiveGrid& grid_;
};

}  // namespace darkroom::listao
