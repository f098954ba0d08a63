#pragma once
// How messages name an image's channels — "R, G, B", or with their types
// "Z (float32), objectId (uint32)"; "no channels" for an image without — in
// one place. Header-only, so a plugin uses it without linking more.
#include <darkroom/buffer.h>

#include <string>

namespace darkroom {

inline std::string channelListText(const Buffer& b, bool withTypes = false) {
    std::string s;
    for (const auto& c : b.channels()) {
        if (!s.empty()) s += ", ";
        s += c.name;
        if (withTypes) s += std::string(" (") + toString(c.type) + ")";
    }
    return s.empty() ? std::string("no channels") : s;
}

}  // namespace darkroom
