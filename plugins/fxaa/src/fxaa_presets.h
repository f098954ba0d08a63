#pragma once
// The quality presets of FXAA 3.11 (Lottes 2011): for each, the offsets (in
// pixels) of the successive end-of-edge search steps. The first step is taken
// before the first sample, the last one after the last sample (it is a guess
// at how far the edge runs on beyond the searched span).
#include <string>
#include <vector>

namespace darkroom::fxaa {

struct Preset {
    std::string name;          // "10" ... "39"
    std::vector<float> steps;  // P0, P1, ... (FXAA_QUALITY__PS entries)
};

// All published presets: 10-15, 20-29, 39.
const std::vector<Preset>& presets();
std::vector<std::string> presetNames();

// The preset called `name`; throws darkroom::Error listing the valid names.
const Preset& preset(const std::string& name);

}  // namespace darkroom::fxaa
