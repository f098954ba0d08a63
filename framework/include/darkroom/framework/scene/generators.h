#pragma once
// Built-in scene generators: geometry made in code, so the demo and the tests
// need no download. Owned by the generators work; the scene file calls generate().
#include <darkroom/export.h>
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

}  // namespace darkroom
