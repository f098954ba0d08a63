#include "exr_attributes.h"

#include <darkroom/error.h>
#include <darkroom/limits.h>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <map>

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

bool readInt32(std::ifstream& in, std::int32_t& v) {
    unsigned char b[4];
    if (!in.read(reinterpret_cast<char*>(b), 4)) return false;
    v = std::int32_t(std::uint32_t(b[0]) | (std::uint32_t(b[1]) << 8) | (std::uint32_t(b[2]) << 16) |
                     (std::uint32_t(b[3]) << 24));
    return true;
}

// The attribute types OpenEXR 3.1 reads at their own size whatever size the
// header declares (TypedAttribute<T>::readValueFrom reads T's fields): the
// walk must step over the same bytes OpenEXR does, or a lying declared size
// hides the attributes after it.
int naturalSize(const std::string& type) {
    static const std::map<std::string, int> sizes = {
        {"box2i", 16}, {"box2f", 16}, {"chromaticities", 32}, {"compression", 1}, {"deepImageState", 1},
        {"double", 8}, {"envmap", 1},  {"float", 4},           {"int", 4},          {"keycode", 28},
        {"lineOrder", 1}, {"m33d", 72}, {"m33f", 36},         {"m44d", 128},       {"m44f", 64},
        {"rational", 8}, {"tiledesc", 9}, {"timecode", 8},    {"v2d", 16},         {"v2f", 8},
        {"v2i", 8},      {"v3d", 24},   {"v3f", 12},          {"v3i", 12},
    };
    auto it = sizes.find(type);
    return it == sizes.end() ? -1 : it->second;
}

// What one header tells about the memory OpenEXR and our reader will need.
struct Part {
    bool hasWindow = false;
    std::int32_t window[4] = {0, 0, 0, 0};  // xMin, yMin, xMax, yMax
    std::uint64_t channels = 0;
    bool hasTiles = false;
    std::uint32_t tile[2] = {0, 0};
};

// Checked before OpenEXR opens the file: InputFile's constructor sizes its
// line buffers from the data window (an 867-byte file declaring 4,195,297 x
// 131,073 pixels made it clear gigabytes, found by the exr harness).
void checkPart(const Part& part, const std::string& path) {
    if (part.hasWindow) {
        const std::int64_t w = std::int64_t(part.window[2]) - part.window[0] + 1;
        const std::int64_t h = std::int64_t(part.window[3]) - part.window[1] + 1;
        if (w > 0 && h > 0) {  // an empty window is OpenEXR's to report
            checkImagePixels(std::uint64_t(w), std::uint64_t(h), path);
            // Saturating: a pixel limit raised near 2^64 must not let the
            // product wrap round to a small number.
            const std::uint64_t pixels = std::uint64_t(w) * std::uint64_t(h);  // both < 2^32
            const std::uint64_t perPixel = std::max<std::uint64_t>(part.channels, 1) * 4;
            const std::uint64_t bytes =
                pixels > UINT64_MAX / perPixel ? UINT64_MAX : pixels * perPixel;
            checkBytes(Limit::DecodedBytes, bytes, path,
                       std::to_string(part.channels) + " channels of " + std::to_string(w) + " x " +
                           std::to_string(h) + " pixels");
        }
    }
    if (part.hasTiles) checkImagePixels(part.tile[0], part.tile[1], path + ": OpenEXR tile size");
}

[[noreturn]] void failSize(const std::string& path, const std::string& name, const std::string& type, std::int64_t at,
                           std::int64_t declared, std::int64_t left) {
    throw InputError(path + ": OpenEXR attribute '" + name + "' (" + type + ") at byte " + std::to_string(at) +
                     " declares " + std::to_string(declared) + " bytes, but the file has " + std::to_string(left) +
                     " left (a truncated or corrupt header)");
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
    Part part;
    std::string name, type;
    for (;;) {
        const std::int64_t at = std::int64_t(in.tellg());
        if (!readName(in, maxName, name)) return;
        if (name.empty()) {
            // The end of a header; a multi-part file ends its list of headers
            // with one more empty name.
            if (headerHasAttributes) checkPart(part, path);
            if (!multiPart || !headerHasAttributes) return;
            headerHasAttributes = false;
            part = Part();
            continue;
        }
        headerHasAttributes = true;
        std::int32_t length = 0;
        if (!readName(in, maxName, type) || !readInt32(in, length)) return;
        if (type == "chlist") {
            // OpenEXR reads a channel list up to its empty name, whatever the
            // declared size: follow it the same way (name, then 16 bytes).
            std::string channel;
            while (readName(in, maxName, channel) && !channel.empty()) {
                in.seekg(16, std::ios::cur);
                ++part.channels;
            }
            if (!in) return;
            continue;
        }
        const std::int64_t left = size - std::int64_t(in.tellg());
        if (length < 0) failSize(path, name, type, at, length, left);
        if (const int natural = naturalSize(type); natural >= 0) {
            if (name == "dataWindow" && type == "box2i") {
                part.hasWindow = true;
                for (std::int32_t& v : part.window)
                    if (!readInt32(in, v)) return;
            } else if (name == "tiles" && type == "tiledesc") {
                std::int32_t x = 0, y = 0;
                if (!readInt32(in, x) || !readInt32(in, y)) return;
                part.hasTiles = true;
                part.tile[0] = std::uint32_t(x);
                part.tile[1] = std::uint32_t(y);
                in.seekg(1, std::ios::cur);
            } else {
                in.seekg(natural, std::ios::cur);
            }
            continue;
        }
        if (type == "preview") {
            // Width and height, then 4 bytes a pixel, allocated as declared.
            std::int32_t w = 0, h = 0;
            if (!readInt32(in, w) || !readInt32(in, h)) return;
            // OpenEXR reads both as unsigned: up to 2^64 pixels, so compare
            // without multiplying by 4 (the fuzzer's find: 4 w h overflowed).
            const std::uint64_t pixels = std::uint64_t(std::uint32_t(w)) * std::uint32_t(h);
            const std::int64_t room = left - 8;
            if (room < 0 || pixels > std::uint64_t(room) / 4)
                throw InputError(path + ": OpenEXR attribute '" + name + "' (preview) at byte " + std::to_string(at) +
                                 " declares " + std::to_string(std::uint32_t(w)) + " x " +
                                 std::to_string(std::uint32_t(h)) + " pixels of 4 bytes, but the file has " +
                                 std::to_string(std::max<std::int64_t>(room, 0)) +
                                 " bytes left (a truncated or corrupt header)");
            in.seekg(std::int64_t(pixels) * 4, std::ios::cur);
            continue;
        }
        if (length > left) failSize(path, name, type, at, length, left);
        if (type == "stringvector") {
            // Each string's own length is allocated before it is read.
            std::int64_t read = 0;
            while (read < length) {
                std::int32_t n = 0;
                if (!readInt32(in, n)) return;
                read += 4;
                if (n < 0 || n > length - read)
                    throw InputError(path + ": OpenEXR attribute '" + name + "' (stringvector) at byte " +
                                     std::to_string(at) + " holds a string of " + std::to_string(n) +
                                     " bytes, but the attribute has " + std::to_string(length - read) +
                                     " left (a corrupt header)");
                in.seekg(n, std::ios::cur);
                read += n;
            }
            continue;
        }
        in.seekg(length, std::ios::cur);
    }
}

}  // namespace darkroom::io
