// Families of small or thin geometry in front of a backdrop: sphere particles
// and round lines of a given projected size, a thin slab near a wall, and a
// staircase of depth steps.
#include "stress_families.h"
#include "stress_geometry.h"

#include <darkroom/scene/hash_random.h>

#include <algorithm>
#include <cmath>

namespace darkroom::stress::detail {

namespace {

std::shared_ptr<const Scene> sceneOf(std::vector<SceneObject> objects) {
    auto scene = std::make_shared<Scene>();
    scene->objects = std::move(objects);
    return scene;
}

constexpr std::uint64_t kSeed = 0x5eed5ca1e5ull;

// Particles and streamlines share this frame: eye on +z looking at the
// origin from 10 units, subject within a thin layer around z = 0, a wall
// behind it filling the view.
constexpr double kSubjectDepth = 10.0;

Camera frontCamera(const Options& o) {
    return lookAt({0, 0, kSubjectDepth}, {0, 0, 0}, {0, 1, 0}, o.width, o.height);
}

// A wall z = zWall facing the camera, large enough to fill the view at its
// depth, with a constant point field.
SceneObject backdrop(const Camera& c, double zWall, const std::string& field, double value) {
    const double depth = kSubjectDepth - zWall;
    const double half = 2.0 * halfViewHeight(c, depth) * std::max(1.0, aspect(c)) + 1.0;
    return gridSurface("backdrop", {0, 0, zWall}, {1, 0, 0}, {0, 1, 0}, linspace(-half, half, 8),
                       linspace(-half, half, 8), field, [value](const Vec3&) { return value; });
}

}  // namespace

void buildParticles(StressScene& s, double knob, const Options& o) {
    s.camera = frontCamera(o);
    const double pixel = s.camera.pixelSizeAt(kSubjectDepth);
    const double hh = halfViewHeight(s.camera, kSubjectDepth), hw = hh * aspect(s.camera);
    const double r = knob * pixel;
    s.aoRadius = 0.12 * hh;  // 6% of the view height
    // Centres fill 70% of the view across and a layer of +-aoRadius/2 in
    // depth (projected radii within ~2% of the knob). About 30% of the
    // cloud's image area is covered, so the count goes with 1 / r^2; capped
    // so tiny particles on large images stay cheap.
    const double cx = 0.7 * hw, cy = 0.7 * hh, cz = 0.5 * s.aoRadius;
    const double areaPx = (2 * cx / pixel) * (2 * cy / pixel);
    const auto count = std::size_t(std::clamp(std::lround(0.3 * areaPx / (kPi * knob * knob)), 3l, 20000l));
    SceneObject cloud;
    cloud.name = "particles";
    cloud.representation = Representation::Points;
    ScalarField value{"value", ScalarField::Association::Point, {}};
    for (std::size_t i = 0; i < count; ++i) {
        using generators::hashUniform;
        const Vec3 p{cx * (2 * hashUniform(kSeed, i, 0) - 1), cy * (2 * hashUniform(kSeed, i, 1) - 1),
                     cz * (2 * hashUniform(kSeed, i, 2) - 1)};
        pushVertex(cloud, p, r);
        value.values.push_back(float(0.2 + 0.8 * hashUniform(kSeed, i, 3)));
    }
    cloud.fields.push_back(std::move(value));
    // The wall sits a quarter AO radius behind the deepest sphere's back.
    const double zWall = -(cz + r + 0.25 * s.aoRadius);
    s.colorField = "value";
    s.scene = sceneOf({std::move(cloud), backdrop(s.camera, zWall, s.colorField, 0.0)});
    s.fieldMin = 0.0;
    s.fieldMax = 1.0;
    s.focalDistance = kSubjectDepth;  // the cloud's centre
    s.description = "A cloud of equal spheres of a given projected radius just in front of a wall: "
                    "sub-pixel particles alias and vanish from depth, and their contact shadows on the "
                    "wall test screen-space AO.";
}

void buildStreamlines(StressScene& s, double knob, const Options& o) {
    s.camera = frontCamera(o);
    const double hh = halfViewHeight(s.camera, kSubjectDepth), hw = hh * aspect(s.camera);
    s.aoRadius = 0.12 * hh;
    const int lines = 30, verticesPerLine = 256;
    const double cz = 0.5 * s.aoRadius;
    SceneObject obj;
    obj.name = "streamlines";
    obj.representation = Representation::Lines;
    ScalarField time{"time", ScalarField::Association::Point, {}};
    double maxRadius = 0.0;
    for (int k = 0; k < lines; ++k) {
        using generators::hashUniform;
        // Lines run left to right, spread over 70% of the view height, each a
        // smooth wave in y and z: a bundle that bends around like a flow.
        const double y0 = hh * (-0.7 + 1.4 * (k + 0.5) / lines), amp = hh * (0.08 + 0.08 * hashUniform(kSeed, k, 10));
        const double freq = 0.7 + 0.8 * hashUniform(kSeed, k, 11), phase = 2 * kPi * hashUniform(kSeed, k, 12);
        const double zPhase = 2 * kPi * hashUniform(kSeed, k, 13);
        const auto base = std::uint32_t(obj.vertexCount());
        for (int i = 0; i < verticesPerLine; ++i) {
            const double t = double(i) / (verticesPerLine - 1);
            const Vec3 p{hw * (-0.8 + 1.6 * t), y0 + amp * std::sin(2 * kPi * freq * t + phase) + 0.2 * hh * (t - 0.5) * (t - 0.5),
                         cz * std::sin(2 * kPi * t + zPhase)};
            // Radius from the planar depth of this very vertex, so the width
            // in pixels is the knob all along the line.
            const double radius = 0.5 * knob * s.camera.pixelSizeAt(s.camera.depthOf(p));
            maxRadius = std::max(maxRadius, radius);
            pushVertex(obj, p, radius);
            time.values.push_back(float(t));
            if (i + 1 < verticesPerLine) obj.indices.push_back(base + std::uint32_t(i));
        }
    }
    obj.fields.push_back(std::move(time));
    const double zWall = -(cz + maxRadius + 0.25 * s.aoRadius);
    s.colorField = "time";
    s.scene = sceneOf({std::move(obj), backdrop(s.camera, zWall, s.colorField, 0.0)});
    s.fieldMin = 0.0;
    s.fieldMax = 1.0;
    s.focalDistance = kSubjectDepth;
    s.description = "A bundle of smooth round lines of a given width in pixels just in front of a wall: "
                    "sub-pixel lines alias and break up, and their thin silhouettes defeat depth-based "
                    "normals and AO.";
}

void buildSlabs(StressScene& s, double knob, const Options& o) {
    const double R = 0.5, thickness = 0.02 * R, gap = knob * R;
    s.aoRadius = R;
    // Slab 4 x 3 units, its back face `gap` in front of the wall z = 0,
    // seen from 14 units, 15 degrees right and 10 degrees up of its normal.
    const Vec3 centre{0, 0, gap + 0.5 * thickness};
    const double dist = 14.0, yaw = 15.0 * kPi / 180.0, pitch = 10.0 * kPi / 180.0;
    const Vec3 dir{std::sin(yaw) * std::cos(pitch), std::sin(pitch), std::cos(yaw) * std::cos(pitch)};
    s.camera = lookAt(centre + dir * dist, centre, {0, 1, 0}, o.width, o.height);
    s.colorField = "part";
    const double half = 60.0;
    s.scene = sceneOf({gridSurface("wall", {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, linspace(-half, half, 4),
                                   linspace(-half, half, 4), s.colorField, [](const Vec3&) { return 0.0; }),
                       box("slab", {-2, -1.5, gap}, {2, 1.5, gap + thickness}, s.colorField,
                           [](const Vec3&) { return 1.0; })});
    s.fieldMin = 0.0;
    s.fieldMax = 1.0;
    s.focalDistance = dist;
    s.description = "A thin slab (1/50 of the AO radius thick) parallel to a wall at a given gap: depth "
                    "buffers cannot tell the slab's thickness or the empty gap behind it, so screen-space "
                    "AO and depth of field bleed across.";
}

void buildStaircase(StressScene& s, double knob, const Options& o) {
    const double R = 0.5, h = knob * R, d = std::max(2.0 * R, 1.5 * h);
    const int steps = 6;
    s.aoRadius = R;
    // Steps descend away from the camera (-z), so each riser faces away and
    // every tread edge is a depth discontinuity over the tread below. Treads
    // are at least 1.5 step heights deep so that, from 50 degrees above,
    // part of every tread shows.
    const Vec3 target{0, -0.5 * steps * h, -0.5 * steps * d};
    const double span = 0.5 * std::hypot(steps * d, steps * h), dist = span / std::tan(20.0 * kPi / 180.0) * 0.8;
    const double elevation = 50.0 * kPi / 180.0;
    s.camera = lookAt(target + Vec3{0, std::sin(elevation), std::cos(elevation)} * dist, target, {0, 1, 0}, o.width,
                      o.height);
    // Far enough sideways, towards the camera and away that nothing else shows.
    const double far = 10.0 * dist + 10.0, bottom = -steps * h;
    s.colorField = "height";
    auto height = [](const Vec3& p) { return p.y; };
    std::vector<SceneObject> objects;
    for (int i = 0; i < steps; ++i) {
        const double zFront = i == 0 ? far : -i * d;
        objects.push_back(box("step " + std::to_string(i + 1), {-far, bottom, -(i + 1) * d}, {far, -i * h, zFront},
                              s.colorField, height));
    }
    objects.push_back(gridSurface("floor", {0, bottom, 0}, {1, 0, 0}, {0, 0, -1}, linspace(-far, far, 4),
                                  linspace(steps * d, far, 4), s.colorField, height));
    s.scene = sceneOf(std::move(objects));
    s.fieldMin = bottom;
    s.fieldMax = 0.0;
    s.focalDistance = dist;
    s.description = "A staircase of boxes descending away from the camera: each tread edge is a depth step "
                    "of the given height, where depth-based normals, AO and depth of field smear across.";
}

}  // namespace darkroom::stress::detail
