#pragma once
// Built-in scene generators: geometry made in code, so the demo and the tests
// need no download. The scene file calls generate() for `generator: NAME`.
//
//   isosurface   level set of demoField() by marching tetrahedra (Surface;
//                point fields `height` = z, `field`, `gradient magnitude`)
//   streamlines  RK4 streamlines of the ABC flow (Lines; `time`, `speed`)
//   particles    hashed particle halo around the blobs (Points; `value`, `id`)
//   maxima       spheres at the local maxima of demoField() (Points; `value`)
//   plane        a subdivided square, e.g. a floor (Surface; `height`)
//   demo         isosurface + streamlines + particles + maxima in one view
//
// Every generator works with no parameters; docs/generators.md lists them all.
// Output is deterministic: random positions come from hashing (seed, index).
#include <darkroom/export.h>
#include <darkroom/math.h>
#include <darkroom/scene.h>

#include <map>
#include <string>
#include <vector>

namespace darkroom {

// Names accepted by generate(), e.g. "isosurface", "streamlines", "particles", "maxima".
DARKROOM_API std::vector<std::string> generatorNames();

// Builds the objects of a generator. `params` are the scene file's key/value
// pairs as text (e.g. {"resolution": "64"}); unknown keys or bad values throw
// darkroom::Error naming the generator, the key and what was expected.
DARKROOM_API std::vector<SceneObject> generate(const std::string& name,
                                               const std::map<std::string, std::string>& params);

// What a scene asks of generate() beyond the generator's parameters.
struct GenerateOptions {
    // Surfaces that know their exact normals carry them as vertex normals
    // (vertex_normals.h): the isosurface, the demo field's gradient.
    bool vertexNormals = false;
};
DARKROOM_API std::vector<SceneObject> generate(const std::string& name,
                                               const std::map<std::string, std::string>& params,
                                               const GenerateOptions& options);

namespace generators {

// The demo's analytic scalar field on [-1,1]^3: a sum of Gaussian blobs (some
// overlapping, some too weak to reach the default isovalue 0.5 so their maxima
// float outside the surface) plus a tilted ring whose strength varies as
// cos(3 angle), giving a torus with three maxima. Below 0.04 on the cube's
// faces, so every level set above that is closed inside the cube. Peaks at ~1.07.
DARKROOM_API double demoField(const Vec3& p);
DARKROOM_API Vec3 demoFieldGradient(const Vec3& p);

// Velocity of the ABC flow u = (A sin z + C cos y, B sin x + A cos z,
// C sin y + B cos x) with its 2π-periodic cell mapped onto [-1,1]^3
// (x_flow = π (p + 1)), expressed in world units per unit of flow time.
DARKROOM_API Vec3 abcVelocity(const Vec3& p, double a, double b, double c);

}  // namespace generators
}  // namespace darkroom
