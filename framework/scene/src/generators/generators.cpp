// generate(): the registry of built-in generators, and the demo scene that
// combines them.
#include "builtin_generators.h"

#include <darkroom/error.h>
#include <darkroom/scene/generators.h>

#include <fmt/format.h>

#include <functional>
#include <utility>

namespace darkroom {
namespace {
using namespace generators;

using Builder = std::function<std::vector<SceneObject>(GeneratorParams&)>;

// Demo: everything in one view of [-1,1]^3. Thinner tubes and fewer lines
// than the streamline defaults so the flow does not hide the surface.
std::vector<SceneObject> demo(GeneratorParams& p) {
    IsosurfaceOptions iso;
    iso.resolution = p.integer("resolution", iso.resolution, 2, 512);
    iso.isovalue = p.number("isovalue", iso.isovalue, 0.05, 1.2);
    iso.normals = p.vertexNormals();
    StreamlineOptions lines;
    lines.count = p.integer("streamlines", 40, 0, 100000);
    lines.radius = 0.005;
    ParticleOptions particles;
    particles.count = p.integer("particles", particles.count, 0, 10000000);
    particles.isovalue = iso.isovalue;
    const int seed = p.integer("seed", 1, 0, 2147483647);
    lines.seed = std::uint64_t(seed);
    particles.seed = std::uint64_t(seed) + 6;
    p.finish();
    return {buildIsosurface(iso), buildStreamlines(lines), buildParticles(particles), buildMaxima({})};
}

const std::vector<std::pair<std::string, Builder>>& builders() {
    static const std::vector<std::pair<std::string, Builder>> list{
        {"isosurface", [](GeneratorParams& p) { return std::vector{buildIsosurface(readIsosurfaceOptions(p))}; }},
        {"streamlines", [](GeneratorParams& p) { return std::vector{buildStreamlines(readStreamlineOptions(p))}; }},
        {"particles", [](GeneratorParams& p) { return std::vector{buildParticles(readParticleOptions(p))}; }},
        {"tracers", [](GeneratorParams& p) { return std::vector{buildTracers(readTracerOptions(p))}; }},
        {"maxima", [](GeneratorParams& p) { return std::vector{buildMaxima(readMaximaOptions(p))}; }},
        {"plane", [](GeneratorParams& p) { return std::vector{buildPlane(readPlaneOptions(p))}; }},
        {"demo", demo},
    };
    return list;
}

}  // namespace

std::vector<std::string> generatorNames() {
    std::vector<std::string> names;
    for (const auto& [name, builder] : builders()) names.push_back(name);
    return names;
}

std::vector<SceneObject> generate(const std::string& name, const std::map<std::string, std::string>& params) {
    return generate(name, params, GenerateOptions{});
}

std::vector<SceneObject> generate(const std::string& name, const std::map<std::string, std::string>& params,
                                  const GenerateOptions& options) {
    for (const auto& [n, builder] : builders()) {
        if (n != name) continue;
        GeneratorParams p(name, params, options.vertexNormals);
        return builder(p);
    }
    throw Error(fmt::format("unknown generator '{}' (expected one of: {})", name, fmt::join(generatorNames(), ", ")));
}

namespace generators {
void appendVertex(SceneObject& o, const Vec3& p, double radius) {
    o.vertices.insert(o.vertices.end(), {float(p.x), float(p.y), float(p.z), float(radius)});
}
}  // namespace generators

}  // namespace darkroom
