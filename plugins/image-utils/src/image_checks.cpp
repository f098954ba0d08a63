#include "image_checks.h"

#include <darkroom/channel_text.h>
#include <darkroom/error.h>

namespace darkroom::utils {

std::string sizeText(const Buffer& b) { return std::to_string(b.width()) + "x" + std::to_string(b.height()); }

const float* requireFloatChannel(const Buffer& b, const std::string& name, const std::string& port) {
    if (const float* p = b.hostFloat(name)) return p;
    throw Error("the image on '" + port + "' has no float32 channel '" + name + "'; it has " +
                channelListText(b));
}

void requireSameSize(const Buffer& a, const Buffer& b, const std::string& portA, const std::string& portB) {
    if (a.width() == b.width() && a.height() == b.height()) return;
    throw Error("'" + portA + "' is " + sizeText(a) + " but '" + portB + "' is " + sizeText(b) +
                "; both must have the same size (use Resize)");
}

}  // namespace darkroom::utils
