#pragma once
// Normals and positions reconstructed from planar depth and the camera, shared
// by the Normals pass and by IBS (its lighting term, when the input has no N.*).
#include <darkroom/camera.h>
#include <darkroom/context.h>

#include <string>
#include <vector>

namespace darkroom::passes {

// How the tangent along each image axis is estimated.
//   Central       (P[x+1] - P[x-1]) / 2: second-order on smooth surfaces,
//                 wrong across depth discontinuities.
//   Nearest       the one-sided difference towards the neighbour with the
//                 smaller depth difference.
//   Extrapolated  per side, predict the centre from two neighbours (linearly
//                 in 1/Z for perspective, in Z for orthographic cameras, the
//                 quantities that are affine in the image on a plane) and use
//                 the side that predicts it better; when both predict it
//                 equally well (within a factor 2), the central difference.
enum class NormalMethod { Central, Nearest, Extrapolated };

const std::vector<std::string>& normalMethodNames();  // {"central", "nearest", "extrapolated"}
NormalMethod parseNormalMethod(const std::string& name);

// Destinations, each may be null. View space is right-handed: x right, y up,
// z towards the viewer (so a surface facing the camera has Nv.z > 0 in an
// orthographic view). Pixels without a surface (non-finite Z) get NaN.
struct NormalOutputs {
    float* view[3] = {nullptr, nullptr, nullptr};   // Nv.x, Nv.y, Nv.z
    float* world[3] = {nullptr, nullptr, nullptr};  // N.x, N.y, N.z
    float* position[3] = {nullptr, nullptr, nullptr};  // P.x, P.y, P.z (world)
};

// `camera` must have the buffer's resolution (see requireCamera). An axis with
// no surface neighbour at all (a one-pixel-wide feature, a 1x1 image) takes the
// camera's own axis as tangent, i.e. the normal leans towards the viewer.
void reconstructNormals(Context& ctx, const float* depth, int width, int height,
                        const Camera& camera, NormalMethod method, const NormalOutputs& out);

// Rotates world-space normals into the view space above (for inputs that
// already carry captured N.*).
void worldToViewNormals(Context& ctx, const float* const world[3], std::size_t count,
                        const Camera& camera, float* const view[3]);

}  // namespace darkroom::passes
