#pragma once
// Layered G-buffers (issue 30): a capture with `channels: {layers: K}` keeps
// the K nearest surface crossings along each pixel's ray (a closed surface
// gives its front and its back), so opacity can be chosen after capture.
//
// Naming: layer 0, the nearest, has the plain channel names every pass reads
// (Z, N.x, N.y, N.z, objectId, primitiveId, the scalars); layer k >= 1 has
// the same names prefixed "layer<k>." (layer1.Z, layer1.N.x, layer1.height).
// Layers are in increasing depth (Z <= layer1.Z <= layer2.Z ...); where a
// pixel's ray crosses fewer surfaces, the missing layers hold Z = +inf, NaN
// in float channels and 0xffffffff in id channels, as background does.
// A pass that needs one surface (SSAO, IBS, SSDoF, Normals) reads the plain
// names, i.e. the front layer, and ignores the others.
#include <darkroom/buffer.h>

#include <cstdlib>
#include <string>
#include <string_view>
#include <utility>

namespace darkroom::layers {

inline const std::string kPrefix = "layer";

// The name of channel `name` in layer `layer` (0 = the front layer: `name`).
inline std::string channel(const std::string& name, int layer) {
    return layer == 0 ? name : kPrefix + std::to_string(layer) + "." + name;
}

// The layer of a channel name and its name within the layer:
// "layer2.N.x" -> (2, "N.x"), "height" -> (0, "height"). A name that only
// looks like a prefix ("layer0.Z", "layer.Z", "layerX.Z") is layer 0's.
inline std::pair<int, std::string> parse(std::string_view channelName) {
    if (channelName.substr(0, kPrefix.size()) != kPrefix) return {0, std::string(channelName)};
    const std::size_t dot = channelName.find('.', kPrefix.size());
    if (dot == std::string_view::npos || dot == kPrefix.size() || dot - kPrefix.size() > 4)
        return {0, std::string(channelName)};
    int k = 0;
    for (std::size_t i = kPrefix.size(); i < dot; ++i) {
        const char c = channelName[i];
        if (c < '0' || c > '9') return {0, std::string(channelName)};
        k = 10 * k + (c - '0');
    }
    if (k == 0) return {0, std::string(channelName)};
    return {k, std::string(channelName.substr(dot + 1))};
}

// How many layers `b` holds: 1 + the number of consecutive layer<k>.Z
// channels (k = 1, 2, ...). 1 for an ordinary G-buffer.
inline int count(const Buffer& b) {
    int k = 1;
    while (b.hasChannel(channel("Z", k))) ++k;
    return k;
}

}  // namespace darkroom::layers
