#pragma once
// Stress scenes for the accuracy harness (issue 6): small scenes made in code,
// each with its camera, built where image-space passes are known to hold (open
// plane, floor-wall corner, with analytic AO) and where they are known to fail
// (sub-pixel particles and lines, thin slabs, depth steps, grazing angles,
// geometry across the image border, high-frequency stripes). A family sweeps
// one knob (projected radius, gap, angle...) so the harness can find where a
// method's error crosses a threshold.
//
// Deterministic: the same family, knob value and options give the same scene.
//
// Conventions the tests and the harness rely on (docs/stress-scenes.md has
// the table): every camera is perspective with a 40 degree vertical field of
// view; the image centre looks at the main subject, whose planar depth is
// focalDistance (particles: the cloud's centre, where the projected radius is
// exactly the knob; streamlines: every vertex's radius is width / 2 pixels at
// its own depth; grazing: where the centre ray meets the plane; stripes: the
// centre's period is the knob). analyticAo is set for plane, grazing and
// stripes (1: open planes) and corner (cornerAo of the distance to the other
// plane).
#include <darkroom/camera.h>
#include <darkroom/export.h>
#include <darkroom/accuracy/reference.h>
#include <darkroom/math.h>
#include <darkroom/scene.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace darkroom::stress {

struct Options {
    int width = 128;
    int height = 128;
};

struct StressScene {
    std::string family;  // e.g. "particles"
    std::string name;    // family plus knob, e.g. "particles-r2" (file-name safe)
    // The knob this family sweeps, with its unit, e.g. "projected radius (px)";
    // empty for a family with no knob (knobValue is then 0).
    std::string knob;
    double knobValue = 0.0;
    std::string description;  // one sentence: what it is and what it stresses

    std::shared_ptr<const Scene> scene;
    Camera camera;  // perspective unless stated, options.width x options.height

    // What to colour-map: a point or cell field every object carries, and a
    // range covering its values.
    std::string colorField;
    double fieldMin = 0.0, fieldMax = 1.0;

    // An AO radius (world units) at which the scene shows its effect, and a
    // focal distance (planar depth) for depth-of-field tests.
    double aoRadius = 0.1;
    double focalDistance = 1.0;

    // Exact AO at a world point on the visible geometry for a world radius,
    // when it is known in closed form (plane, corner); empty otherwise.
    std::function<double(const Vec3& point, double radius, reference::AoWeighting)> analyticAo;
};

// The families, in a stable order: plane, corner, terrain, particles,
// streamlines, slabs, staircase, grazing, border, gyroid, stripes, shells,
// sheets.
DARKROOM_API std::vector<std::string> families();

// The knob values a family is swept over (e.g. particles: projected radii
// 0.5 ... 20 px; streamlines: widths 0.25 ... 4 px; grazing: 80 ... 89
// degrees); a single 0 for a family with no knob.
DARKROOM_API std::vector<double> knobValues(const std::string& family);

// One scene of a family at a knob value (any value in the family's range, not
// only the listed ones). Throws darkroom::Error naming the family and what was
// expected on an unknown family or a knob value out of range.
DARKROOM_API StressScene make(const std::string& family, double knobValue, const Options& options = {});

// make() for every knob value of the family.
DARKROOM_API std::vector<StressScene> sweep(const std::string& family, const Options& options = {});

// Cosine- and uniform-weighted AO of a point at distance d from an infinite
// plane occluder (perpendicular to the receiver's plane) with occluders
// counted within radius R: the floor-wall corner's closed form.
//   cosine:  1 - (acos k - k sqrt(1 - k^2)) / pi,   uniform: (1 + k) / 2,   k = min(|d| / R, 1)
// Throws darkroom::Error when R <= 0.
DARKROOM_API double cornerAo(double distance, double radius, reference::AoWeighting weighting);

}  // namespace darkroom::stress
