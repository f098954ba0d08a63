// Scene YAML: parseSceneFile in memory; mesh files it names are looked up in
// an empty folder of this process's own. Generators run for real, but with
// their sizes capped (framework/scene/src/generator_seam.h): an input naming
// a few default isosurfaces cost seconds of field evaluation under the
// sanitizers, and the corpus filled with such inputs until the harness ran 30
// inputs a second. Parameters that do not read as numbers are left alone, so
// the generators' own checks still see them.
#include "harness.h"
#include "../../../framework/scene/src/generator_seam.h"

#include <darkroom/error.h>
#include <darkroom/scene/scene_file.h>

#include <cstdlib>
#include <map>
#include <string>

namespace {

// Largest sizes a fuzz input may ask of each generator: tens of milliseconds.
const std::map<std::string, std::map<std::string, double>> kCaps = {
    {"isosurface", {{"resolution", 12}}},
    {"maxima", {{"resolution", 8}}},
    {"streamlines", {{"count", 8}, {"steps", 50}}},
    {"particles", {{"count", 200}}},
    {"plane", {{"subdivisions", 16}}},
    {"demo", {{"resolution", 12}, {"streamlines", 8}, {"particles", 200}}},
};

void capSizes(const std::string& generator, std::map<std::string, std::string>& params) {
    const auto caps = kCaps.find(generator);
    if (caps == kCaps.end()) return;
    for (const auto& [key, cap] : caps->second) {
        auto it = params.find(key);
        if (it == params.end()) {
            // The default would be larger; but `steps` may not join `length`.
            if (!(key == "steps" && params.count("length"))) params[key] = std::to_string(int(cap));
            continue;
        }
        char* end = nullptr;
        const double v = std::strtod(it->second.c_str(), &end);
        if (end != it->second.c_str() && *end == '\0' && v > cap) it->second = std::to_string(int(cap));
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    darkroom::scene_detail::generatorParameterFilter = capSizes;
    try {
        (void)darkroom::parseSceneFile(std::string(fuzz::text(data, size)), "fuzz.yaml", fuzz::scratchFolder());
    } catch (const darkroom::Error&) {
    }
    return 0;
}
