// Families of separate objects: shapes cut by the image border against an
// empty background, and a gyroid (an isosurface of many tunnels).
#include "stress_families.h"
#include "stress_geometry.h"

#include <darkroom/scene/marching_tetrahedra.h>

#include <cmath>

namespace darkroom::stress::detail {

void buildBorder(StressScene& s, double, const Options& o) {
    s.camera = lookAt({0, 0, 10}, {0, 0, 0}, {0, 1, 0}, o.width, o.height);
    const Camera& c = s.camera;
    const double W = c.width, H = c.height;
    s.colorField = "object";
    auto constant = [](double v) { return [v](const Vec3&) { return v; }; };
    // Centres placed in image coordinates: the first sphere's centre on the
    // left border, the second's on the top border, the third and the box
    // inside. Radii are fractions of the half view height at their depth.
    auto at = [&](double fx, double fy, double depth) { return c.worldPosition(fx * W, fy * H, depth); };
    auto hh = [&](double depth) { return halfViewHeight(c, depth); };
    const double boxHalf = 0.2 * hh(10.5);
    const Vec3 boxCentre = at(0.78, 0.7, 10.5);
    const Vec3 half{boxHalf, boxHalf, boxHalf};
    auto scene = std::make_shared<Scene>();
    scene->objects = {sphereMesh("left sphere", at(0.0, 0.45, 10), 0.35 * hh(10), 48, s.colorField, constant(0)),
                      sphereMesh("top sphere", at(0.62, 0.0, 11), 0.3 * hh(11), 48, s.colorField, constant(1)),
                      sphereMesh("inner sphere", at(0.35, 0.62, 9), 0.22 * hh(9), 48, s.colorField, constant(2)),
                      box("box", boxCentre - half, boxCentre + half, s.colorField, constant(3), 35.0 * kPi / 180.0)};
    s.scene = scene;
    s.fieldMin = 0.0;
    s.fieldMax = 3.0;
    s.aoRadius = 0.3;
    s.focalDistance = 10.0;
    s.description = "Three spheres and a box against an empty background, one sphere cut by the left and one "
                    "by the top image border: screen-space passes lack the geometry outside the image and "
                    "must treat the background's infinite depth.";
}

void buildGyroid(StressScene& s, double, const Options& o) {
    // sin x cos y + sin y cos z + sin z cos x = 0 in a cube 1.5 periods
    // (3 pi) wide, cut open at the cube's faces; seen from near a corner.
    const double a = 1.5 * kPi;
    auto gyroid = [](const Vec3& p) {
        return std::sin(p.x) * std::cos(p.y) + std::sin(p.y) * std::cos(p.z) + std::sin(p.z) * std::cos(p.x);
    };
    generators::LevelSetGrid grid;
    grid.lo = {-a, -a, -a};
    grid.hi = {a, a, a};
    grid.samples = 72;
    const generators::LevelSetMesh mesh = generators::extractLevelSet(gyroid, grid, 0.0, /*refine=*/true);
    SceneObject obj;
    obj.name = "gyroid";
    obj.representation = Representation::Surface;
    obj.indices = mesh.triangles;
    ScalarField f{"radius", ScalarField::Association::Point, {}};
    for (const Vec3& p : mesh.positions) {
        pushVertex(obj, p);
        f.values.push_back(float(length(p)));
    }
    obj.fields.push_back(std::move(f));
    const double dist = 18.0;  // the cube's corners just inside the view
    s.camera = lookAt(normalize(Vec3{1.0, 0.8, 1.2}) * dist, {0, 0, 0}, {0, 1, 0}, o.width, o.height);
    auto scene = std::make_shared<Scene>();
    scene->objects.push_back(std::move(obj));
    s.scene = scene;
    s.colorField = "radius";
    s.fieldMin = 0.0;
    s.fieldMax = a * std::sqrt(3.0);
    s.aoRadius = 0.5;
    s.focalDistance = dist;
    s.description = "A gyroid minimal surface in a cube of 1.5 periods, cut open at the faces: deep tunnels, "
                    "saddles everywhere and many overlapping depth layers, a realistic hard case.";
}

}  // namespace darkroom::stress::detail
