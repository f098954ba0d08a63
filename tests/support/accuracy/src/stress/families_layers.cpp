// Families with several surfaces along each ray, for transparency (issue 30):
// nested closed shells (isosurfaces of one radial field, each crossed twice)
// and a stack of parallel sheets. Their knob is the number of surfaces, so
// the depth complexity a ray meets is known: 2 x shells at the centre, the
// sheet count everywhere the stack covers.
#include "stress_families.h"
#include "stress_geometry.h"

#include <cmath>
#include <string>

namespace darkroom::stress::detail {

namespace {

std::shared_ptr<const Scene> sceneOf(std::vector<SceneObject> objects) {
    auto scene = std::make_shared<Scene>();
    scene->objects = std::move(objects);
    return scene;
}

}  // namespace

void buildShells(StressScene& s, double knob, const Options& o) {
    const int shells = int(std::lround(knob));
    s.camera = lookAt({0, 0, 6}, {0, 0, 0}, {0, 1, 0}, o.width, o.height);
    s.colorField = "level";
    // Radii evenly spaced up to 80 % of the half view height: the field
    // |x| at levels R i / N, the outer shells translucent over the inner.
    const double outer = 0.8 * halfViewHeight(s.camera, 6.0);
    std::vector<SceneObject> objects;
    for (int i = 1; i <= shells; ++i) {
        const double r = outer * i / shells;
        objects.push_back(sphereMesh("shell " + std::to_string(i), {0, 0, 0}, r, 64, s.colorField,
                                     [r](const Vec3&) { return r; }));
    }
    s.scene = sceneOf(std::move(objects));
    s.fieldMin = 0.0;
    s.fieldMax = outer;
    s.aoRadius = 0.1 * outer;
    s.focalDistance = 6.0;
    s.description = "Nested closed spheres (isosurfaces of one radial field) seen from the front: a ray "
                    "through the centre crosses every shell twice, so transparency needs two layers per shell "
                    "there and fewer towards the rims.";
}

void buildSheets(StressScene& s, double knob, const Options& o) {
    const int sheets = int(std::lround(knob));
    s.colorField = "sheet";
    // Parallel sheets 0.15 apart along z, each 5 x 5, seen from 8 units
    // 20 degrees off their normal: every ray through the middle of the image
    // crosses all of them.
    const double gap = 0.15, yaw = 20.0 * kPi / 180.0;
    const double mid = 0.5 * gap * (sheets - 1);
    s.camera = lookAt(Vec3{std::sin(yaw), 0, std::cos(yaw)} * 8.0 + Vec3{0, 0, mid}, {0, 0, mid}, {0, 1, 0},
                      o.width, o.height);
    std::vector<SceneObject> objects;
    for (int i = 0; i < sheets; ++i) {
        const double value = sheets > 1 ? double(i) / (sheets - 1) : 0.0;
        objects.push_back(gridSurface("sheet " + std::to_string(i + 1), {0, 0, gap * i}, {1, 0, 0}, {0, 1, 0},
                                      linspace(-2.5, 2.5, 2), linspace(-2.5, 2.5, 2), s.colorField,
                                      [value](const Vec3&) { return value; }));
    }
    s.scene = sceneOf(std::move(objects));
    s.fieldMin = 0.0;
    s.fieldMax = 1.0;
    s.aoRadius = 0.2;
    s.focalDistance = 8.0;
    s.description = "A stack of parallel sheets a little apart, seen obliquely: the middle of the image has a "
                    "depth complexity of the sheet count, the many thin layers of a translucent stack.";
}

}  // namespace darkroom::stress::detail
