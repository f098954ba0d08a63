#include "exr_attributes.h"

#include <darkroom/error.h>

#include <cstdint>
#include <fstream>

namespace darkroom::io {

namespace {

// A NUL-terminated name of at most `max` characters; false when there is none.
bool readName(std::ifstream& in, std::size_t max, std::string& out) {
    out.clear();
    char c;
    while (in.get(c)) {
        if (c == '\0') return true;
        if (out.size() == max) return false;
        out += c;
    }
    return false;
}

}  // namespace

void checkExrAttributeSizes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return;
    in.seekg(0, std::ios::end);
    const std::int64_t size = std::int64_t(in.tellg());
    in.seekg(0);
    unsigned char head[8];
    if (!in.read(reinterpret_cast<char*>(head), 8)) return;
    if (head[0] != 0x76 || head[1] != 0x2f || head[2] != 0x31 || head[3] != 0x01) return;
    // OpenEXR reads names of up to 255 characters whatever the long-names
    // flag says. Version flag 0x10 (byte 5): multi-part.
    const std::size_t maxName = 255;
    const bool multiPart = (head[5] & 0x10) != 0;
    bool headerHasAttributes = false;
    std::string name, type;
    for (;;) {
        const std::int64_t at = std::int64_t(in.tellg());
        if (!readName(in, maxName, name)) return;
        if (name.empty()) {
            // The end of a header; a multi-part file ends its list of headers
            // with one more empty name.
            if (!multiPart || !headerHasAttributes) return;
            headerHasAttributes = false;
            continue;
        }
        headerHasAttributes = true;
        unsigned char bytes[4];
        if (!readName(in, maxName, type) || !in.read(reinterpret_cast<char*>(bytes), 4)) return;
        const std::int32_t length = std::int32_t(std::uint32_t(bytes[0]) | (std::uint32_t(bytes[1]) << 8) |
                                                 (std::uint32_t(bytes[2]) << 16) | (std::uint32_t(bytes[3]) << 24));
        if (type == "chlist") {
            // OpenEXR reads a channel list up to its empty name, whatever the
            // declared size: follow it the same way (name, then 16 bytes).
            std::string channel;
            while (readName(in, maxName, channel) && !channel.empty()) in.seekg(16, std::ios::cur);
            if (!in) return;
            continue;
        }
        const std::int64_t left = size - std::int64_t(in.tellg());
        if (length < 0 || length > left)
            throw InputError(path + ": OpenEXR attribute '" + name + "' (" + type + ") at byte " + std::to_string(at) +
                             " declares " + std::to_string(length) + " bytes, but the file has " +
                             std::to_string(left) + " left (a truncated or corrupt header)");
        in.seekg(length, std::ios::cur);
    }
}

}  // namespace darkroom::io
