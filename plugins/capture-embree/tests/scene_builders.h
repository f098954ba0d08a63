#pragma once
// Small scenes made in code for the capture tests, each with a known analytic
// answer (plane, sphere, tube).
#include <darkroom/camera.h>
#include <darkroom/scene.h>

#include <optional>

namespace darkroom::test {

// A quad of two triangles spanning corner, corner+e1, corner+e1+e2, corner+e2.
// Point field "X" = vertex x; cell field "C" = 10 for triangle 0, 20 for triangle 1.
SceneObject makeQuad(Vec3 corner, Vec3 e1, Vec3 e2);

// A UV sphere triangle mesh (surface) with point field "X" = x.
SceneObject makeSphereMesh(Vec3 center, double radius, int rings, int segments);

// One vertex per centre, drawn as spheres of the given radius.
SceneObject makePoints(const std::vector<Vec3>& centers, double radius);

// A straight polyline from a to b with `segments` segments, drawn as a tube.
// Point field "s" = arc-length parameter in [0, 1]; cell field "line" with a
// single cell (every segment maps to cell 0, value 7).
SceneObject makeTube(Vec3 a, Vec3 b, double radius, int segments);

Camera perspectiveCamera(Vec3 position, Vec3 target, int w, int h, double fovY = 40.0);
Camera orthographicCamera(Vec3 position, Vec3 target, int w, int h, double viewHeight);

// Analytic intersections along origin + t*dir (dir need not be unit); nullopt on a miss.
std::optional<double> intersectPlane(Vec3 o, Vec3 d, Vec3 point, Vec3 normal);
std::optional<double> intersectSphere(Vec3 o, Vec3 d, Vec3 center, double radius);
// Infinite cylinder of axis a->b; also returns the axial parameter of the hit (0 at a, 1 at b).
std::optional<double> intersectCylinder(Vec3 o, Vec3 d, Vec3 a, Vec3 b, double radius, double* axial = nullptr);
// Ray against triangle i of a surface object (plane of the triangle, no edge test).
std::optional<double> intersectTrianglePlane(Vec3 o, Vec3 d, const SceneObject& obj, std::uint32_t tri);

Vec3 vertex(const SceneObject& obj, std::uint32_t i);

}  // namespace darkroom::test
