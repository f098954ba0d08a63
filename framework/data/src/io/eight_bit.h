#pragma once
// A float buffer as the 8-bit sRGB pixels of a PNG, JPEG, TIFF...: which
// channels (image_io.h's rules), linear -> sRGB code values, straight alpha.
// Shared by the native PNG writer and the OpenImageIO module. Internal.
#include "srgb_code.h"

#include <darkroom/buffer.h>
#include <darkroom/data/image_io.h>

#include <string>
#include <vector>

namespace darkroom::io {

struct EightBitPixels {
    int channels = 0;                 // 1 grey, 2 grey+alpha, 3 RGB, 4 RGBA
    bool alpha = false;               // the last channel is alpha
    std::vector<unsigned char> data;  // interleaved, rows top to bottom
};

// The channels an 8-bit file takes from `image` (1 grey, 2 grey+alpha, 3 RGB,
// 4 RGBA), chosen by image_io.h's rules or named in `options`.
struct EightBitSource {
    int width = 0, height = 0;
    int channels = 0;
    bool alpha = false;
    std::vector<const float*> planes;  // one per channel, in file order
};
EightBitSource chooseEightBit(const Buffer& image, const std::string& path, const ImageWriteOptions& options,
                              bool alphaAllowed);

// The code of one value. Colour: linear -> sRGB code value, rounded to
// nearest (srgb_code.h), NaN and v <= 0 -> 0, v >= 1 -> 255. Alpha, stored
// linearly: lround(v * 255), NaN and v <= 0 -> 0; for m >= 0, lround(m) is
// floor(m + 0.5) computed exactly in double. The rows below are encoded a
// vector at a time to the same bytes (eight_bit_rows.cpp; the tests compare).
inline unsigned char encodeColourValue(float v) {
    if (!(v > 0.0f)) return 0;
    if (v >= 1.0f) return 255;
    return srgbCode(v);
}
inline unsigned char encodeAlphaValue(float v) {
    if (!(v > 0.0f)) return 0;
    if (v >= 1.0f) return 255;
    return (unsigned char)(int)(double(v * 255.0f) + 0.5);
}

// Their interleaved 8-bit codes, row y at rows + y * rowBytes (every byte of
// the width * channels written), so that a PNG writer can encode straight
// into its filter rows.
void encodeEightBitRows(const EightBitSource& source, unsigned char* rows, std::size_t rowBytes);

// `alphaAllowed`: false for formats without alpha (JPEG), which then get grey
// or RGB. Throws darkroom::Error naming `path` when the channels cannot be
// chosen or are not float32.
EightBitPixels encodeEightBit(const Buffer& image, const std::string& path, const ImageWriteOptions& options,
                              bool alphaAllowed);

}  // namespace darkroom::io
