#pragma once
// A value input that names a channel of the node's image input
// (ColorMapping's `channel`, Mix's `factorChannel`, Compositing's
// `depthChannel`): a string port whose name ends in "channel". Its widget
// offers the input's channels in a drop-down (free text still allowed).
#include <darkroom/port.h>

#include <algorithm>
#include <cctype>
#include <string>

namespace editor {

inline bool isChannelPort(const darkroom::PortSpec& p) {
    if (p.type != darkroom::PortType::String) return false;
    static const std::string kEnd = "channel";
    if (p.name.size() < kEnd.size()) return false;
    return std::equal(kEnd.rbegin(), kEnd.rend(), p.name.rbegin(),
                      [](char a, char b) { return a == std::tolower(static_cast<unsigned char>(b)); });
}

}  // namespace editor
