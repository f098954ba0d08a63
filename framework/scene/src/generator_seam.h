#pragma once
// A seam for the scene file's fuzz harness (tests/fuzz/harnesses/scene.cpp),
// internal to the framework: when set, the scene parser hands a generator's
// name and parameters through it before darkroom::generate() sees them. The
// harness caps the sizes so that each input costs its parsing, not seconds of
// isosurface arithmetic; nothing else sets it.
#include <map>
#include <string>

namespace darkroom::scene_detail {

using GeneratorParameterFilter = void (*)(const std::string& generator, std::map<std::string, std::string>& params);
extern GeneratorParameterFilter generatorParameterFilter;

}  // namespace darkroom::scene_detail
