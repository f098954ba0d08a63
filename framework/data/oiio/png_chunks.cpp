#include "png_chunks.h"

#include <darkroom/error.h>

#include <cstdint>
#include <cstring>
#include <fstream>

namespace darkroom::oiio_module {

void checkPngChunks(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return;  // OpenImageIO reports an unreadable file in its words
    in.seekg(0, std::ios::end);
    const std::uint64_t size = std::uint64_t(in.tellg());
    in.seekg(0);
    char signature[8];
    if (!in.read(signature, 8) || std::memcmp(signature, "\x89PNG\r\n\x1a\n", 8) != 0) return;
    std::uint64_t offset = 8;
    // Each chunk: 4-byte big-endian length, 4-byte type, data, 4-byte CRC.
    unsigned char head[8];
    while (offset + 8 <= size && in.read(reinterpret_cast<char*>(head), 8)) {
        const std::uint64_t length =
            (std::uint64_t(head[0]) << 24) | (std::uint64_t(head[1]) << 16) | (std::uint64_t(head[2]) << 8) | head[3];
        const std::string type(reinterpret_cast<const char*>(head) + 4, 4);
        const std::uint64_t left = size - offset - 8;
        if (length > left)
            throw InputError(path + ": PNG chunk '" + type + "' at byte " + std::to_string(offset) + " declares " +
                             std::to_string(length) + " bytes, but the file has " + std::to_string(left) +
                             " left (a truncated or corrupt PNG)");
        if (type == "IEND") return;
        offset += 8 + length + 4;
        in.seekg(std::streamoff(offset));
    }
}

}  // namespace darkroom::oiio_module
