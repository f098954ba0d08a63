#pragma once
// Exact ray casting of spheres into a G-buffer: every pixel centre's ray (the
// camera's own Camera::ray) is intersected analytically with the spheres whose
// screen footprint covers it; the nearest hit wins. No acceleration library:
// spheres are binned by the rows their exact perspective bounds cover.
#include <darkroom/camera.h>
#include <darkroom/context.h>

#include <vector>

namespace darkroom::spheres {

struct Sphere {
    Vec3 center;
    double radius = 0;
};

// Per pixel: planar depth (+inf where no sphere), the index of the sphere hit
// (-1 where none) and its world-space unit normal (NaN where none).
struct Hits {
    std::vector<float> depth;
    std::vector<int> index;
    std::vector<float> normal[3];
};

// Continuous pixel bounds [x0, x1) x [y0, y1) of a sphere's image (exact
// tangent bounds for perspective: the silhouette's extent, Mara & McGuire
// 2013), unclipped; false when it is entirely behind a perspective camera.
// A sphere reaching behind the image plane covers the whole image.
bool screenBounds(const Camera& camera, const Sphere& s, double& x0, double& y0, double& x1, double& y1);

// The nearest positive ray parameter t of o + t d on the sphere, or a negative
// number when the ray misses it (t is planar depth for Camera::ray's rays).
double intersect(const Vec3& o, const Vec3& d, const Sphere& s);

// Casts every pixel of a width x height image (the camera's resolution) in
// parallel; ties go to the lower index, so the result does not depend on the
// thread count.
Hits castSpheres(Context& ctx, const Camera& camera, const std::vector<Sphere>& spheres);

}  // namespace darkroom::spheres
