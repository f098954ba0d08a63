#pragma once
// The cosine-weighted occlusion of one primitive seen from a receiver, in
// closed form: what fraction of the receiver's hemisphere, weighted by the
// cosine to its normal ((1/pi) * integral of V(w) (w . n)+ dw), is covered by
// a sphere, or by a thin round line, within a maximum distance R (ray-traced
// AO's definition with a hard cut). Pure functions on floats, no state, so
// the tests can check them against numerical integration.
#include <darkroom/view_geometry.h>

namespace darkroom::listao {

// Projected solid angle / pi of a spherical cap of angular radius sigma
// (given as sin^2 sigma) whose axis makes an angle theta with the normal
// (given as cos theta), clipped by the receiver's horizon. Above the horizon
// this is sin^2(sigma) cos(theta); a cap straddling the horizon takes the
// exact form of the clipped integral (the one known for sphere lights, after
// Snyder 1996, "Area light sources for real-time graphics").
float capOcclusion(float cosTheta, float sin2Sigma);

// sin^2 of the angular radius of the directions from a receiver that hit a
// sphere of radius r whose centre is at distance d, within distance R: the
// whole silhouette cap when its rim is nearer than R, else the cap of
// directions whose hit distance d cos(b) - sqrt(r^2 - d^2 sin^2 b) is below R
// (cos b = (d^2 + R^2 - r^2) / (2 d R), from the triangle receiver, centre,
// hit point). 0 when the sphere is beyond R; -1 when the receiver is inside
// or on the sphere (its own sphere: a convex body does not occlude itself).
float sphereCapWithin(float d, float r, float R);

// Occlusion of receiver p with unit normal n by the sphere (c, r) within R.
float sphereOcclusion(V3f p, V3f n, V3f c, float r, float R);

// Occlusion of receiver p with unit normal n by a round line from a to b
// whose radius goes linearly from ra to rb, within R. The line is thin
// (radius small against the distance), so each piece ds subtends
// 2 asin(r / d) across and |t x u| ds / d along, u the unit direction to it:
// the integral of that times (n . u)+ / pi over the part of the line nearer
// than R + r, by Gauss-Legendre on pieces no longer than half their distance.
// Pieces the receiver lies within (its own line) count nothing.
float tubeOcclusion(V3f p, V3f n, V3f a, V3f b, float ra, float rb, float R);

// The same integral by one midpoint sample, for a piece of length `len`,
// radius r, unit direction t, whose middle is at v (distance d) from the
// receiver, far for its length (d > 4 len: relative error about
// (len / d)^2 / 24, under 0.3 %) and wholly nearer than R.
float thinPiece(V3f v, float d, V3f n, V3f t, float r, float len);

}  // namespace darkroom::listao
