#pragma once
// Error messages shared by the utility nodes.
#include <darkroom/buffer.h>

#include <string>

namespace darkroom::utils {

// "640x480".
std::string sizeText(const Buffer& b);
// The float32 channel `name`, or a darkroom::Error naming the port and the
// channels the image has (the host adds the node).
const float* requireFloatChannel(const Buffer& b, const std::string& name, const std::string& port);
// Throws unless both images have the same size, naming both sizes.
void requireSameSize(const Buffer& a, const Buffer& b, const std::string& portA, const std::string& portB);

}  // namespace darkroom::utils
