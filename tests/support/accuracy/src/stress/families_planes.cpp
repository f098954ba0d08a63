// Families built on planes: the open plane and floor-wall corner (analytic
// AO known), a height-field terrain, a plane at grazing angles and a
// perspective plane of hard-edged stripes.
#include "stress_families.h"
#include "stress_geometry.h"

#include <algorithm>
#include <cmath>

namespace darkroom::stress::detail {

namespace {

std::shared_ptr<const Scene> sceneOf(std::vector<SceneObject> objects) {
    auto scene = std::make_shared<Scene>();
    scene->objects = std::move(objects);
    return scene;
}

const Vec3 kX{1, 0, 0}, kUp{0, 1, 0};

// Nodes from 0 to 8 in steps of 0.25 (fine where the corner is seen), then
// coarse out to 50 so the planes reach far beyond any AO radius and the view.
std::vector<double> cornerDistances() {
    std::vector<double> v = linspace(0.0, 8.0, 32);
    for (double d : {10.0, 14.0, 20.0, 30.0, 50.0}) v.push_back(d);
    return v;
}

std::vector<double> cornerLateral() {
    std::vector<double> v;
    for (double d : {-50.0, -30.0, -20.0, -14.0, -10.0}) v.push_back(d);
    for (double d : linspace(-8.0, 8.0, 32)) v.push_back(d);
    for (double d : {10.0, 14.0, 20.0, 30.0, 50.0}) v.push_back(d);
    return v;
}

}  // namespace

void buildPlane(StressScene& s, double, const Options& o) {
    // 40 x 40 plane y = 0 seen at 45 degrees from 5.7 units: the top of the
    // view meets it 4.6 units behind the centre, well inside its edge.
    s.camera = lookAt({0, 4, 4}, {0, 0, 0}, kUp, o.width, o.height);
    s.colorField = "pattern";
    auto pattern = [](const Vec3& p) { return 0.5 + 0.5 * std::sin(0.5 * p.x) * std::sin(0.5 * p.z); };
    s.scene = sceneOf({gridSurface("plane", {0, 0, 0}, kX, {0, 0, -1}, linspace(-20, 20, 80),
                                   linspace(-20, 20, 80), s.colorField, pattern)});
    s.fieldMin = 0.0;
    s.fieldMax = 1.0;
    s.aoRadius = 0.5;
    s.focalDistance = s.camera.depthOf({0, 0, 0});
    s.description = "An open 40 x 40 plane seen at 45 degrees: nothing occludes it, so exact AO is 1 "
                    "everywhere and any darkening is the method's own error.";
    s.analyticAo = [](const Vec3&, double, reference::AoWeighting) { return 1.0; };
}

void buildCorner(StressScene& s, double, const Options& o) {
    // Floor y = 0 (z >= 0) and wall z = 0 (y >= 0), 100 units wide and 50
    // deep, seen from 8 units at 40 degrees above the floor (so floor and
    // wall are lit differently): the AO radius of 1 spans 11-13% of the
    // image height at the joint, and the top of the view meets the wall
    // 2.9 units up.
    const double elevation = 40.0 * kPi / 180.0;
    s.camera = lookAt(Vec3{0, std::sin(elevation), std::cos(elevation)} * 8.0, {0, 0, 0}, kUp, o.width, o.height);
    s.colorField = "distance";
    // Distance to the joint line, clamped at 8 (a grid node, so the
    // interpolated field equals the function exactly).
    auto distance = [](const Vec3& p) { return std::min(std::sqrt(p.y * p.y + p.z * p.z), 8.0); };
    const auto d = cornerDistances(), lateral = cornerLateral();
    s.scene = sceneOf({gridSurface("floor", {0, 0, 0}, {0, 0, 1}, kX, d, lateral, s.colorField, distance),
                       gridSurface("wall", {0, 0, 0}, kUp, {-1, 0, 0}, d, lateral, s.colorField, distance)});
    s.fieldMin = 0.0;
    s.fieldMax = 8.0;
    s.aoRadius = 1.0;
    s.focalDistance = s.camera.depthOf({0, 0, 0});
    s.description = "A floor meeting a wall at a right angle, seen across the joint: AO has a closed form "
                    "(cornerAo of the distance to the other plane), the reference for occlusion on contact.";
    s.analyticAo = [](const Vec3& p, double radius, reference::AoWeighting w) {
        // p lies on the plane it is nearest to; the other plane occludes.
        const double d = std::abs(p.y) <= std::abs(p.z) ? std::abs(p.z) : std::abs(p.y);
        return cornerAo(d, radius, w);
    };
}

void buildTerrain(StressScene& s, double, const Options& o) {
    const double a = std::max(1.0, double(o.width) / double(o.height));
    const double halfZ = 12.0, halfX = 12.0 * a;
    auto height = [](double x, double z) {
        auto hill = [](double x, double z, double cx, double cz, double s2) {
            return std::exp(-((x - cx) * (x - cx) + (z - cz) * (z - cz)) / s2);
        };
        return 1.4 * hill(x, z, 3, -2, 8) + 1.0 * hill(x, z, -4, 3, 5) - 0.8 * hill(x, z, -1, -6, 6) +
               0.9 * hill(x, z, 7, 6, 3) + 0.25 * std::sin(0.9 * x + 0.3) * std::cos(0.7 * z) +
               0.12 * std::sin(1.7 * x - 1.3 * z);
    };
    // 45 degrees down from 12 units: the top of the view meets the ground
    // about 9.7 units behind the centre, inside the 24 x 24 grid.
    const double dist = 12.0;
    s.camera = lookAt({0, dist * std::sqrt(0.5), dist * std::sqrt(0.5)}, {0, 0, 0}, kUp, o.width, o.height);
    s.colorField = "height";
    // u along z, v along x: the grid's normal is +y, the displacement is up.
    s.scene = sceneOf({gridSurface(
        "terrain", {0, 0, 0}, {0, 0, 1}, kX, linspace(-halfZ, halfZ, 100),
        linspace(-halfX, halfX, int(std::lround(100 * a))), s.colorField, [](const Vec3& p) { return p.y; },
        [&](double u, double v) { return height(v, u); })});
    s.fieldMin = -1.0;
    s.fieldMax = 1.6;
    s.aoRadius = 1.0;
    s.focalDistance = dist;
    s.description = "A smooth height field of hills and ripples seen obliquely: moderate, everywhere-varying "
                    "occlusion and curvature with no discontinuities, the benign case.";
}

void buildGrazing(StressScene& s, double knob, const Options& o) {
    // Eye 1 unit above the plane y = 0, looking down -z at `knob` degrees
    // from the normal. The up vector is exact, so 0 degrees (straight down)
    // has a basis too.
    const double alpha = knob * kPi / 180.0, c = std::cos(alpha), sn = std::sin(alpha);
    const Vec3 eye{0, 1, 0}, fwd{0, -c, -sn};
    s.camera = lookAt(eye, eye + fwd, {0, sn, -c}, o.width, o.height);
    // Ground distance s along -z from the eye's foot, on nodes s = 2^t - 1
    // (t evenly spaced), mirrored behind: fine near the eye, coarse towards
    // the far edge 2000 units away, where one pixel spans a lot of ground.
    const double reach = 2000.0, tMax = std::log2(1.0 + reach);
    std::vector<double> ts = linspace(-tMax, tMax, 400), vs;
    for (double t : ts) vs.push_back((t < 0 ? -1.0 : 1.0) * (std::exp2(std::abs(t)) - 1.0));
    vs.front() = -reach, vs.back() = reach;
    s.colorField = "log distance";
    // sign(s) log2(1 + |s|): smooth, linear in t, so it changes evenly from
    // the bottom of the image to the horizon.
    auto logDistance = [](const Vec3& p) {
        const double g = -p.z;
        return (g < 0 ? -1.0 : 1.0) * std::log2(1.0 + std::abs(g));
    };
    s.scene = sceneOf(
        {gridSurface("plane", {0, 0, 0}, kX, {0, 0, -1}, linspace(-reach, reach, 16), vs, s.colorField, logDistance)});
    s.fieldMin = -tMax;
    s.fieldMax = tMax;
    s.aoRadius = 0.25;
    s.focalDistance = 1.0 / std::max(c, 1e-6);  // planar depth of the centre hit (the centre ray is forward)
    s.description = "One open plane seen at a grazing angle from its normal: exact AO is 1 and normals are "
                    "constant, but depth changes steeply across each pixel.";
    s.analyticAo = [](const Vec3&, double, reference::AoWeighting) { return 1.0; };
}

void buildStripes(StressScene& s, double knob, const Options& o) {
    // Eye 1 unit above the plane y = 0, 30 degrees down: the centre ray meets
    // the plane at planar depth 2, ground distance sqrt(3). A ground step dz
    // there moves the image by dz sin(30 deg) / pixelSize pixels, so this
    // period gives `knob` pixels per period at the image centre.
    const double theta = 30.0 * kPi / 180.0, height = 1.0;
    const Vec3 eye{0, height, 0}, fwd{0, -std::sin(theta), -std::cos(theta)};
    s.camera = lookAt(eye, eye + fwd, kUp, o.width, o.height);
    const double depth = height / std::sin(theta), centre = height / std::tan(theta);
    const double period = knob * s.camera.pixelSizeAt(depth) / std::sin(theta);
    // Strips cover ground distances 0.5 .. 8 (the view spans 0.84 .. 5.7);
    // boundaries at centre + (j + 1/2) period put the centre mid-stripe.
    const double nearEdge = 0.5, farEdge = 8.0;
    const double halfX = 4.0 * std::max(1.0, double(o.width) / double(o.height));
    const long jMin = long(std::floor((nearEdge - centre) / period)), jMax = long(std::ceil((farEdge - centre) / period));
    SceneObject obj;
    obj.name = "stripes";
    obj.representation = Representation::Surface;
    ScalarField f{"stripe", ScalarField::Association::Cell, {}};
    for (long j = jMin; j <= jMax; ++j) {
        const double g = centre + (double(j) + 0.5) * period;
        pushVertex(obj, {-halfX, 0, -g});
        pushVertex(obj, {halfX, 0, -g});
    }
    for (long j = jMin; j < jMax; ++j) {
        const auto a = std::uint32_t(2 * (j - jMin)), b = a + 1, c = a + 2, d = a + 3;
        obj.indices.insert(obj.indices.end(), {a, d, c, a, b, d});  // normal +y
        const float value = float(((j % 2) + 2) % 2);
        f.values.push_back(value);
        f.values.push_back(value);
    }
    obj.fields.push_back(std::move(f));
    s.colorField = "stripe";
    s.scene = sceneOf({std::move(obj)});
    s.fieldMin = 0.0;
    s.fieldMax = 1.0;
    s.aoRadius = 0.1;
    s.focalDistance = depth;
    s.description = "A plane receding in perspective, striped 0 / 1 by a cell field whose period shrinks "
                    "towards the horizon: hard colour edges below the pixel scale alias.";
    s.analyticAo = [](const Vec3&, double, reference::AoWeighting) { return 1.0; };
}

}  // namespace darkroom::stress::detail
