#include "png_file.h"

#include "eight_bit.h"

#include <darkroom/atomic_file.h>
#include <darkroom/error.h>

#include <png.h>

#include <algorithm>
#include <cctype>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <new>
#include <string>

namespace darkroom::io {

namespace {

// libpng reports errors by longjmp: everything between setjmp and the
// jump is plain data, so no destructor is skipped.
struct PngJob {
    std::string* bytes;  // the encoded file
    int width, height, channels;
    const unsigned char* pixels;
    char message[256];
};

void onError(png_structp png, png_const_charp text) {
    auto* job = static_cast<PngJob*>(png_get_error_ptr(png));
    std::snprintf(job->message, sizeof job->message, "%s", text);
    png_longjmp(png, 1);
}
void onWarning(png_structp, png_const_charp) {}

// The file is encoded in memory and written by writeFileAtomic, whose every
// write, fsync and close is checked (stdio's buffered writes report a failure
// late, if at all).
void onWrite(png_structp png, png_bytep data, png_size_t length) {
    auto* job = static_cast<PngJob*>(png_get_io_ptr(png));
    bool appended = true;
    try {
        job->bytes->append(reinterpret_cast<const char*>(data), length);
    } catch (const std::bad_alloc&) {
        appended = false;
    }
    // Outside the handler: png_error longjmps.
    if (!appended) png_error(png, "not enough memory to encode it");
}
void onFlush(png_structp) {}

bool encode(PngJob& job) {
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &job, onError, onWarning);
    if (!png) {
        std::snprintf(job.message, sizeof job.message, "libpng could not start");
        return false;
    }
    png_infop info = png_create_info_struct(png);
    if (!info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return false;
    }
    png_set_write_fn(png, &job, onWrite, onFlush);
    static const int colourTypes[] = {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA, PNG_COLOR_TYPE_RGB,
                                      PNG_COLOR_TYPE_RGB_ALPHA};
    png_set_IHDR(png, info, png_uint_32(job.width), png_uint_32(job.height), 8, colourTypes[job.channels - 1],
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    // zlib level 2 with the one "up" filter: on rendered images (smooth
    // shading over a flat background) 10-20 % larger than libpng's default
    // (level 6, adaptive filters) in a quarter of its time (docs/formats.md).
    png_set_compression_level(png, 2);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_UP);
    png_write_info(png, info);
    const std::size_t rowBytes = std::size_t(job.width) * std::size_t(job.channels);
    for (int y = 0; y < job.height; ++y)
        png_write_row(png, const_cast<png_bytep>(job.pixels + std::size_t(y) * rowBytes));
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    return true;
}

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
    PngJob job{&bytes, image.width(), image.height(), pixels.channels, pixels.data.data(), {}};
    if (!encode(job)) fail(path, job.message);
    writeFileAtomic(path, bytes);
}

}  // namespace darkroom::io
