#pragma once
// Options and builders of the built-in generators. Each generator reads its
// options from text once (read*Options) and builds from plain values
// (build*), so the demo can combine them without going through text.
#include "generator_params.h"

#include <darkroom/scene.h>

#include <cstdint>

namespace darkroom::generators {

struct IsosurfaceOptions {
    int resolution = 64;  // grid samples per axis over [-1,1]^3
    double isovalue = 0.5;
    bool normals = false;  // vertex normals from the field's gradient (vertex_normals.h)
};
IsosurfaceOptions readIsosurfaceOptions(GeneratorParams& p);
SceneObject buildIsosurface(const IsosurfaceOptions& o);

struct StreamlineOptions {
    int count = 100;         // seeds
    double step = 0.05;      // RK4 time step (flow time units)
    int steps = 200;         // maximum RK4 steps per direction
    double radius = 0.006;   // tube radius, world units
    double a = 1.7320508075688772, b = 1.4142135623730951, c = 1.0;
    std::string direction = "both";  // forward, backward or both from each seed
    std::uint64_t seed = 1;
};
StreamlineOptions readStreamlineOptions(GeneratorParams& p);
SceneObject buildStreamlines(const StreamlineOptions& o);

struct ParticleOptions {
    int count = 2000;
    double radius = 0.012;
    double isovalue = 0.5;  // particles stay outside this level set, denser towards it
    std::uint64_t seed = 7;
};
ParticleOptions readParticleOptions(GeneratorParams& p);
SceneObject buildParticles(const ParticleOptions& o);

struct TracerOptions {
    int count = 20000;
    double radius = 0.006;
    double release = 3.0;       // particles are released over [0, release] and carried until `release`
    double step = 0.02;         // RK4 time step
    double speed = 1.0;         // multiplies the flow's velocity (a slower flow keeps a plume in the cube longer)
    Vec3 source{0.35, -0.25, 0.1};
    double sourceRadius = 0.15;
    double a = 1.7320508075688772, b = 1.4142135623730951, c = 1.0;
    std::uint64_t seed = 11;
};
TracerOptions readTracerOptions(GeneratorParams& p);
SceneObject buildTracers(const TracerOptions& o);

struct MaximaOptions {
    double radius = 0.035;
    int resolution = 40;     // search grid samples per axis
    double minValue = 0.01;  // ignore maxima below this field value
};
MaximaOptions readMaximaOptions(GeneratorParams& p);
SceneObject buildMaxima(const MaximaOptions& o);

struct PlaneOptions {
    double size = 2;
    Vec3 center{0, 0, 0};
    Vec3 normal{0, 0, 1};
    int subdivisions = 1;
};
PlaneOptions readPlaneOptions(GeneratorParams& p);
SceneObject buildPlane(const PlaneOptions& o);

// Stores doubles as the 16-byte x, y, z, radius vertices of a SceneObject.
void appendVertex(SceneObject& o, const Vec3& p, double radius);

}  // namespace darkroom::generators
