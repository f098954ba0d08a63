#include "png_file.h"

#include "eight_bit.h"
#include "png_encoder.h"

#include <darkroom/atomic_file.h>
#include <darkroom/error.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace darkroom::io {

namespace {

// Measured on colour-mapped 1024² and 2048² pictures (docs/performance.md,
// "Codecs"): see there for the bytes against the time of each choice.
constexpr PngEncoding chosenEncoding{PngFilter::Up, 1, Deflater::Runs};

[[noreturn]] void fail(const std::string& path, const std::string& why) {
    throw Error("cannot write image '" + path + "': " + why);
}

}  // namespace

bool isPngPath(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext == ".png";
}

void writePng(const Buffer& image, const std::string& path, const ImageWriteOptions& options) {
    const EightBitPixels pixels = encodeEightBit(image, path, options, true);
    std::string bytes;
    try {
        bytes = encodePng({image.width(), image.height(), pixels.channels, pixels.data.data()}, chosenEncoding);
    } catch (const Error& e) {
        fail(path, e.what());
    }
    // Written by writeFileAtomic, whose every write, fsync and close is
    // checked.
    writeFileAtomic(path, bytes);
}

}  // namespace darkroom::io
