#include "image_checks.h"

#include <darkroom/error.h>

#include <algorithm>

namespace darkroom::utils {

std::string channelList(const Buffer& b) {
    std::string s;
    for (const auto& c : b.channels()) s += (s.empty() ? "" : ", ") + c.name;
    return s.empty() ? std::string("no channels") : s;
}

std::string sizeText(const Buffer& b) { return std::to_string(b.width()) + "x" + std::to_string(b.height()); }

const float* requireFloatChannel(const Buffer& b, const std::string& name, const std::string& node,
                                 const std::string& port) {
    if (const float* p = b.hostFloat(name)) return p;
    throw Error(node + ": the image on '" + port + "' has no float32 channel '" + name + "'; it has " +
                channelList(b));
}

void requireSameSize(const Buffer& a, const Buffer& b, const std::string& node, const std::string& portA,
                     const std::string& portB) {
    if (a.width() == b.width() && a.height() == b.height()) return;
    throw Error(node + ": '" + portA + "' is " + sizeText(a) + " but '" + portB + "' is " + sizeText(b) +
                "; both must have the same size (use Resize)");
}

void copyChannel(const Buffer& from, WritableBuffer& to, const ChannelDesc& channel) {
    const std::size_t n = from.pixelCount();
    if (channel.type == ChannelType::Float32)
        std::copy_n(from.hostFloat(channel.name), n, to.hostFloat(channel.name));
    else
        std::copy_n(from.hostUInt(channel.name), n, to.hostUInt(channel.name));
}

}  // namespace darkroom::utils
