// `tracers`: a dense cloud of particles advected in the ABC flow, released
// from a small ball at a steady rate — the paper's particle case: each
// particle, released at its seed time, is carried by RK4 until the end of
// the release; particles that leave [-1,1]^3 are gone (outflow).
#include "builtin_generators.h"
#include <darkroom/scene/hash_random.h>

#include <darkroom/scene/generators.h>

#include <tbb/parallel_for.h>

#include <cmath>

namespace darkroom::generators {
namespace {

bool inCube(const Vec3& p) { return std::abs(p.x) <= 1 && std::abs(p.y) <= 1 && std::abs(p.z) <= 1; }

// Particle i's seed time and position at the end of the release, or false
// when it left the cube on the way. Draws only from hash(seed, i, k), so the
// cloud is independent of the thread count.
bool advect(const TracerOptions& o, std::uint64_t i, double& seedTime, Vec3& p) {
    seedTime = o.release * (double(i) + hashUniform(o.seed, i, 0)) / double(o.count);
    // A uniform point in the source ball: direction and radius (cube root).
    const double u = 2 * hashUniform(o.seed, i, 1) - 1, phi = 2 * 3.14159265358979 * hashUniform(o.seed, i, 2);
    const double s = std::sqrt(1 - u * u), r = o.sourceRadius * std::cbrt(hashUniform(o.seed, i, 3));
    p = o.source + Vec3{s * std::cos(phi), s * std::sin(phi), u} * r;
    auto v = [&](const Vec3& q) { return abcVelocity(q, o.a, o.b, o.c) * o.speed; };
    const int steps = int(std::ceil((o.release - seedTime) / o.step - 1e-9));
    const double h = steps > 0 ? (o.release - seedTime) / steps : 0;
    for (int k = 0; k < steps; ++k) {
        const Vec3 k1 = v(p), k2 = v(p + k1 * (h / 2)), k3 = v(p + k2 * (h / 2)), k4 = v(p + k3 * h);
        p = p + (k1 + k2 * 2 + k3 * 2 + k4) * (h / 6);
        if (!inCube(p)) return false;
    }
    return inCube(p);
}

}  // namespace

TracerOptions readTracerOptions(GeneratorParams& p) {
    TracerOptions o;
    o.count = p.integer("count", o.count, 0, 10000000);
    o.radius = p.number("radius", o.radius, 0.0, 1.0);
    o.release = p.number("release", o.release, 0.0, 1000.0);
    o.step = p.number("step", o.step, 1e-4, 1.0);
    o.speed = p.number("speed", o.speed, 1e-3, 100.0);
    o.source = p.vec3("source", o.source);
    o.sourceRadius = p.number("source radius", o.sourceRadius, 0.0, 1.0);
    o.seed = std::uint64_t(p.integer("seed", int(o.seed), 0, 2147483647));
    p.finish();
    return o;
}

SceneObject buildTracers(const TracerOptions& o) {
    const auto n = std::size_t(o.count);
    std::vector<Vec3> at(n);
    std::vector<double> seedTime(n);
    std::vector<char> kept(n);
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) { kept[i] = advect(o, i, seedTime[i], at[i]); });
    SceneObject obj;
    obj.name = "tracers";
    obj.representation = Representation::Points;
    ScalarField time{"seed time", ScalarField::Association::Point, {}};
    for (std::size_t i = 0; i < n; ++i) {
        if (!kept[i]) continue;
        obj.vertices.insert(obj.vertices.end(), {float(at[i].x), float(at[i].y), float(at[i].z), float(o.radius)});
        time.values.push_back(float(seedTime[i]));
    }
    obj.fields.push_back(std::move(time));
    return obj;
}

}  // namespace darkroom::generators
