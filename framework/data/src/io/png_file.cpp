#include "png_file.h"

#include "eight_bit.h"
#include "png_encoder.h"
#include "png_up_filter.h"

#include <darkroom/atomic_file.h>
#include <darkroom/error.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace darkroom::io {

namespace {

// Measured on colour-mapped 1024² and 2048² pictures (docs/performance.md,
// "Codecs"): see there for the bytes against the time of each choice. The
// "up" filter is applied by filterUpInPlace below.
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
    const EightBitSource source = chooseEightBit(image, path, options, true);
    const PngPixels shape{image.width(), image.height(), source.channels, nullptr};
    const std::size_t rowBytes = std::size_t(shape.width) * std::size_t(shape.channels) + 1;
    const std::size_t size = filteredSize(shape);
    std::string bytes;
    try {
        // One buffer: the 8-bit codes go straight into the filter rows and
        // are filtered where they lie. A plane's storage, so that a batch
        // writing a PNG per entry reuses the last entry's memory instead of
        // faulting fresh pages in (newHostPlane's recycling).
        const auto storage = newHostPlane((size + 3) / 4, false);
        auto* rows = static_cast<unsigned char*>(storage->writableData());
        encodeEightBitRows(source, rows + 1, rowBytes);
        filterUpInPlace(rows, rowBytes, shape.height);
        bytes = encodeFilteredPng(shape, rows, size, chosenEncoding);
    } catch (const std::bad_alloc&) {
        fail(path, "not enough memory to encode it");
    } catch (const Error& e) {
        fail(path, e.what());
    }
    // Written by writeFileAtomic, whose every write, fsync and close is
    // checked.
    writeFileAtomic(path, bytes);
}

}  // namespace darkroom::io
