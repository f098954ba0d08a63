#include "libpng_encode.h"

#include <png.h>

#include <stdexcept>

namespace darkroom::bench {

namespace {

void onWrite(png_structp png, png_bytep data, png_size_t length) {
    static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<const char*>(data), length);
}
void onFlush(png_structp) {}

}  // namespace

// As framework/data/src/io/png_file.cpp wrote it before libdeflate (same
// chunks), with the level and filters as parameters. A libpng error aborts
// the benchmark (longjmp to the setjmp below, then throw).
std::string libpngEncode(const unsigned char* pixels, int width, int height, int channels, int zlibLevel,
                         int filters) {
    std::string bytes;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        throw std::runtime_error("libpng failed");
    }
    png_set_write_fn(png, &bytes, onWrite, onFlush);
    static const int colourTypes[] = {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA, PNG_COLOR_TYPE_RGB,
                                      PNG_COLOR_TYPE_RGB_ALPHA};
    png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), 8, colourTypes[channels - 1],
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    png_set_compression_level(png, zlibLevel);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, filters);
    png_write_info(png, info);
    const std::size_t rowBytes = std::size_t(width) * std::size_t(channels);
    for (int y = 0; y < height; ++y) png_write_row(png, const_cast<png_bytep>(pixels + std::size_t(y) * rowBytes));
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    return bytes;
}

}  // namespace darkroom::bench
