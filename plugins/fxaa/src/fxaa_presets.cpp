#include "fxaa_presets.h"

#include <darkroom/error.h>

namespace darkroom::fxaa {

const std::vector<Preset>& presets() {
    // Published constants of FXAA 3.11. 1x: medium dither (12 is the
    // header's default); 2x: less dither, longer searches; 39: no dither.
    static const std::vector<Preset> table{
        {"10", {1.5f, 3.0f, 12.0f}},
        {"11", {1.0f, 1.5f, 3.0f, 12.0f}},
        {"12", {1.0f, 1.5f, 2.0f, 4.0f, 12.0f}},
        {"13", {1.0f, 1.5f, 2.0f, 2.0f, 4.0f, 12.0f}},
        {"14", {1.0f, 1.5f, 2.0f, 2.0f, 2.0f, 4.0f, 12.0f}},
        {"15", {1.0f, 1.5f, 2.0f, 2.0f, 2.0f, 2.0f, 4.0f, 12.0f}},
        {"20", {1.5f, 2.0f, 8.0f}},
        {"21", {1.0f, 1.5f, 2.0f, 8.0f}},
        {"22", {1.0f, 1.5f, 2.0f, 2.0f, 8.0f}},
        {"23", {1.0f, 1.5f, 2.0f, 2.0f, 2.0f, 8.0f}},
        {"24", {1.0f, 1.5f, 2.0f, 2.0f, 2.0f, 3.0f, 8.0f}},
        {"25", {1.0f, 1.5f, 2.0f, 2.0f, 2.0f, 2.0f, 4.0f, 8.0f}},
        {"26", {1.0f, 1.5f, 2.0f, 2.0f, 2.0f, 2.0f, 2.0f, 4.0f, 8.0f}},
        {"27", {1.0f, 1.5f, 2.0f, 2.0f, 2.0f, 2.0f, 2.0f, 2.0f, 4.0f, 8.0f}},
        {"28", {1.0f, 1.5f, 2.0f, 2.0f, 2.0f, 2.0f, 2.0f, 2.0f, 2.0f, 4.0f, 8.0f}},
        {"29", {1.0f, 1.5f, 2.0f, 2.0f, 2.0f, 2.0f, 2.0f, 2.0f, 2.0f, 2.0f, 4.0f, 8.0f}},
        {"39", {1.0f, 1.0f, 1.0f, 1.0f, 1.0f, 1.5f, 2.0f, 2.0f, 2.0f, 2.0f, 4.0f, 8.0f}},
    };
    return table;
}

std::vector<std::string> presetNames() {
    std::vector<std::string> names;
    for (const auto& p : presets()) names.push_back(p.name);
    return names;
}

const Preset& preset(const std::string& name) {
    for (const auto& p : presets())
        if (p.name == name) return p;
    std::string valid;
    for (const auto& p : presets()) valid += (valid.empty() ? "" : ", ") + p.name;
    throw Error("FXAA: unknown quality preset '" + name + "'; expected one of " + valid);
}

}  // namespace darkroom::fxaa
