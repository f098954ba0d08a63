#include "eight_bit.h"

#include "eight_bit_rows.h"

#include <darkroom/error.h>
#include <darkroom/channel_text.h>

#include <tbb/parallel_for.h>

#include <vector>

namespace darkroom::io {

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& why) {
    throw Error("cannot write image '" + path + "': " + why);
}

std::vector<std::string> defaultChannels(const Buffer& image, const std::string& path) {
    auto isFloat = [&](const char* n) { return image.channelType(n) == ChannelType::Float32; };
    std::vector<std::string> ch;
    if (isFloat("R") && isFloat("G") && isFloat("B"))
        ch = {"R", "G", "B"};
    else if (isFloat("Y"))
        ch = {"Y"};
    else {
        for (const auto& c : image.channels())
            if (c.type == ChannelType::Float32 && c.name != "Z" && c.name != "A") ch.push_back(c.name);
        if (ch.size() != 1)
            fail(path, "cannot choose which channels to write as 8-bit grey or colour from " + channelListText(image, true) +
                           "; name them (ImageWriter's 'channels')");
    }
    if (isFloat("A")) ch.push_back("A");
    return ch;
}

}  // namespace

EightBitSource chooseEightBit(const Buffer& image, const std::string& path, const ImageWriteOptions& options,
                              bool alphaAllowed) {
    std::vector<std::string> names = options.channels.empty() ? defaultChannels(image, path) : options.channels;
    if (names.empty() || names.size() > 4)
        fail(path, "an 8-bit image takes 1 to 4 channels (grey, grey+alpha, RGB, RGBA), not " +
                       std::to_string(names.size()));
    if (!alphaAllowed && (names.size() == 2 || names.size() == 4)) names.pop_back();
    EightBitSource out;
    out.width = image.width();
    out.height = image.height();
    out.channels = int(names.size());
    out.alpha = out.channels == 2 || out.channels == 4;
    for (const auto& name : names) {
        const float* p = image.hostFloat(name);
        if (!p) fail(path, "channel '" + name + "' is not a float32 channel of the image; it has " + channelListText(image, true));
        out.planes.push_back(p);
    }
    return out;
}

void encodeEightBitRows(const EightBitSource& src, unsigned char* rows, std::size_t rowBytes) {
    // Rows in parallel, each a vector of pixels at a time (eight_bit_rows.h).
    const std::size_t w = std::size_t(src.width);
    tbb::parallel_for(0, src.height, [&](int y) {
        const float* planes[4];
        for (int c = 0; c < src.channels; ++c) planes[c] = src.planes[std::size_t(c)] + std::size_t(y) * w;
        encodeEightBitRow(planes, src.channels, src.alpha, w, rows + std::size_t(y) * rowBytes);
    });
}

EightBitPixels encodeEightBit(const Buffer& image, const std::string& path, const ImageWriteOptions& options,
                              bool alphaAllowed) {
    const EightBitSource src = chooseEightBit(image, path, options, alphaAllowed);
    EightBitPixels out;
    out.channels = src.channels;
    out.alpha = src.alpha;
    const std::size_t rowBytes = std::size_t(src.width) * std::size_t(src.channels);
    out.data.resize(rowBytes * std::size_t(src.height));
    encodeEightBitRows(src, out.data.data(), rowBytes);
    return out;
}

}  // namespace darkroom::io
