// `particles`: a halo of particles around the blobs of demoField(), outside
// the isosurface so they are not hidden by it, denser close to it.
#include "builtin_generators.h"
#include <darkroom/scene/hash_random.h>

#include <darkroom/scene/generators.h>

#include <tbb/parallel_for.h>

namespace darkroom::generators {
namespace {

constexpr int kMaxAttempts = 4096;

// Rejection sampling with density (f / isovalue)^2 where f < isovalue, zero
// inside. Particle i draws only from hash(seed, i, attempt), so each particle
// is independent of the others and of the thread count.
Vec3 drawParticle(const ParticleOptions& o, std::uint64_t i) {
    Vec3 p;
    for (int attempt = 0; attempt < kMaxAttempts; ++attempt) {
        const std::uint64_t stream = std::uint64_t(attempt) * 4;
        p = Vec3{2 * hashUniform(o.seed, i, stream) - 1, 2 * hashUniform(o.seed, i, stream + 1) - 1,
                 2 * hashUniform(o.seed, i, stream + 2) - 1} *
            0.98;
        const double f = demoField(p) / o.isovalue;
        if (f < 1 && hashUniform(o.seed, i, stream + 3) < f * f) return p;
    }
    return p;  // practically unreachable (acceptance is a few percent); keeps the count exact
}

}  // namespace

ParticleOptions readParticleOptions(GeneratorParams& p) {
    ParticleOptions o;
    o.count = p.integer("count", o.count, 0, 10000000);
    o.radius = p.number("radius", o.radius, 0.0, 1.0);
    o.isovalue = p.number("isovalue", o.isovalue, 0.05, 1.2);
    o.seed = std::uint64_t(p.integer("seed", int(o.seed), 0, 2147483647));
    p.finish();
    return o;
}

SceneObject buildParticles(const ParticleOptions& o) {
    SceneObject obj;
    obj.name = "particles";
    obj.representation = Representation::Points;
    const auto n = std::size_t(o.count);
    obj.vertices.resize(n * 4);
    ScalarField value{"value", ScalarField::Association::Point, std::vector<float>(n)};
    ScalarField id{"id", ScalarField::Association::Point, std::vector<float>(n)};
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
        const Vec3 p = drawParticle(o, i);
        float* v = &obj.vertices[i * 4];
        v[0] = float(p.x), v[1] = float(p.y), v[2] = float(p.z), v[3] = float(o.radius);
        value.values[i] = float(demoField(p));
        id.values[i] = float(i);  // exact below 2^24 particles
    });
    obj.fields = {std::move(value), std::move(id)};
    return obj;
}

}  // namespace darkroom::generators
