#pragma once
// What an image file holds, read from its header alone. Internal to the
// framework (the Cinema consistency checks compare it with data.csv).
#include <darkroom/buffer.h>

#include <string>
#include <vector>

namespace darkroom::io {

struct ImageHeader {
    int width = 0, height = 0;
    std::vector<ChannelDesc> channels;  // in the order readImage() gives them
};

// EXR natively, any other format through OpenImageIO. Throws darkroom::Error
// naming the file.
ImageHeader readImageHeader(const std::string& path);

}  // namespace darkroom::io
