// Smooth shading normals: the vertex normals of a triangle interpolated
// with the hit's barycentric coordinates, as the scalars are.
#include "gbuffer_writer.h"

#include <cmath>

namespace darkroom::embree {

namespace {

// How far past perpendicular to the ray a normal is turned back towards the
// camera (the cosine between them). Shading passes light back faces as
// their front (Lighting: N flipped where N.V < 0), so a silhouette normal
// leaning a hair away from the camera would be flipped whole; 1e-3 (0.06
// degrees) stays clear of the rounding of V they reconstruct from depth.
constexpr float kTowardsCamera = 1e-3f;

}  // namespace

void GBufferWriter::smoothNormal(const ObjectRef& o, const SurfaceHit& h, const float dir[3], float n[3]) {
    const std::uint32_t* i = o.indices + 3 * std::size_t(h.primID);
    const float w0 = 1.0f - h.u - h.v;
    float s[3];
    for (int a = 0; a < 3; ++a) s[a] = w0 * o.normals[a][i[0]] + h.u * o.normals[a][i[1]] + h.v * o.normals[a][i[2]];
    const float len = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    if (!(len > 1e-6f) || !std::isfinite(len)) return;  // opposite or missing vertex normals: keep the facet's
    // The side of the facing geometric normal: vertex normals follow the
    // triangles' winding, which may face either way from the camera.
    const bool facing = std::isfinite(n[0]);
    const float side = facing ? s[0] * n[0] + s[1] * n[1] + s[2] * n[2] : -(s[0] * dir[0] + s[1] * dir[1] + s[2] * dir[2]);
    const float k = side < 0 ? -1.0f / len : 1.0f / len;
    for (float& x : s) x *= k;
    // Near a silhouette the interpolated normal may lean away from the
    // camera: project it onto the plane across the ray, then tilt it
    // slightly back towards the camera.
    const float dd = dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2];
    const float along = (s[0] * dir[0] + s[1] * dir[1] + s[2] * dir[2]) / std::sqrt(dd);
    if (along > -kTowardsCamera) {
        const float shift = (along + kTowardsCamera) / std::sqrt(dd);
        for (int a = 0; a < 3; ++a) s[a] -= shift * dir[a];
        const float l = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
        if (!(l > 1e-6f)) return;
        for (float& x : s) x /= l;
    }
    n[0] = s[0], n[1] = s[1], n[2] = s[2];
}

}  // namespace darkroom::embree
