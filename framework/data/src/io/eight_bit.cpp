#include "eight_bit.h"

#include "background_spans.h"
#include "srgb_code.h"

#include <darkroom/error.h>
#include <darkroom/channel_text.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstring>
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

// The 8-bit code of alpha, stored linearly: lround(v * 255), NaN and v <= 0
// -> 0. For m >= 0, lround(m) is floor(m + 0.5) computed exactly in double.
inline unsigned char encodeAlpha(float v) {
    if (!(v > 0.0f)) return 0;
    if (v >= 1.0f) return 255;
    return (unsigned char)(int)(double(v * 255.0f) + 0.5);
}

inline unsigned char encodeColour(const SrgbCodeTable& srgb, float v) {
    if (!(v > 0.0f)) return 0;  // also NaN
    if (v >= 1.0f) return 255;
    return srgb.code(v);
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
    // Linear -> sRGB code value (round to nearest) by thresholds
    // (srgb_code.h), NaN -> 0; alpha is stored linearly. Rows in parallel,
    // one channel at a time along a row, so each loop reads one plane.
    const SrgbCodeTable& srgb = srgbCodeTable();
    const std::size_t w = std::size_t(src.width), n = std::size_t(src.channels);
    const std::size_t spans = (w + kBackgroundSpan - 1) / kBackgroundSpan;
    tbb::parallel_for(0, src.height, [&](int y) {
        unsigned char* row = rows + std::size_t(y) * rowBytes;
        // A rendered picture is often mostly background (84 % of the pixels
        // of a colour-mapped 2048² isosurface): spans found by SIMD to hold
        // nothing above zero in a channel give that channel code 0 without a
        // look at each value, and spans that are background in every channel
        // are cleared at once.
        std::vector<std::uint8_t> background(spans * n), everywhere(spans, 1);
        for (std::size_t c = 0; c < n; ++c) {
            markBackgroundSpans(src.planes[c] + std::size_t(y) * w, w, background.data() + c * spans);
            for (std::size_t k = 0; k < spans; ++k) everywhere[k] &= background[c * spans + k];
        }
        for (std::size_t k = 0; k < spans; ++k)
            if (everywhere[k])
                std::memset(row + k * kBackgroundSpan * n, 0, (std::min(w, (k + 1) * kBackgroundSpan) - k * kBackgroundSpan) * n);
        for (std::size_t c = 0; c < n; ++c) {
            const float* s = src.planes[c] + std::size_t(y) * w;
            unsigned char* d = row + c;
            const bool alpha = src.alpha && c == n - 1;
            for (std::size_t k = 0; k < spans; ++k) {
                if (everywhere[k]) continue;
                const std::size_t x0 = k * kBackgroundSpan, x1 = std::min(w, x0 + kBackgroundSpan);
                if (background[c * spans + k])
                    for (std::size_t x = x0; x < x1; ++x) d[x * n] = 0;
                else if (alpha)
                    for (std::size_t x = x0; x < x1; ++x) d[x * n] = encodeAlpha(s[x]);
                else
                    for (std::size_t x = x0; x < x1; ++x) d[x * n] = encodeColour(srgb, s[x]);
            }
        }
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
