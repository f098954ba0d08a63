// Regressions for the image readers (issue 18): sizes are checked from the
// header before a pixel is allocated, and special files are refused at once.
// The forged headers (PNG with its CRCs, TGA, SGI) are written here.
#include "input_error.h"
#include "test_support.h"

#include <darkroom/colormap.h>
#include <darkroom/error.h>
#include <darkroom/data/image_io.h>
#include <darkroom/limits.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <array>
#include <cstdint>
#include <functional>
#include <string>

using namespace darkroom;
using darkroom::test::inputError;
using ::testing::HasSubstr;

namespace {


void putBE32(std::string& s, std::uint32_t v) {
    for (int b = 3; b >= 0; --b) s += char((v >> (8 * b)) & 0xff);
}
void putBE16(std::string& s, std::uint16_t v) {
    s += char(v >> 8);
    s += char(v & 0xff);
}
void putLE16(std::string& s, std::uint16_t v) {
    s += char(v & 0xff);
    s += char(v >> 8);
}

std::uint32_t crc32(const std::string& bytes) {
    std::uint32_t c = 0xffffffffu;
    for (unsigned char b : bytes) {
        c ^= b;
        for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
    }
    return c ^ 0xffffffffu;
}

void pngChunk(std::string& png, const std::string& type, const std::string& data) {
    putBE32(png, std::uint32_t(data.size()));
    png += type + data;
    putBE32(png, crc32(type + data));
}

// A valid PNG header declaring width x height RGBA, with a token IDAT: a
// reader learns the size before it reaches any pixel.
std::string pngHeader(std::uint32_t width, std::uint32_t height) {
    std::string png = "\x89PNG\r\n\x1a\n";
    std::string ihdr;
    putBE32(ihdr, width);
    putBE32(ihdr, height);
    ihdr += std::string{8, 6, 0, 0, 0};  // 8 bits, RGBA, deflate, adaptive filter, no interlace
    pngChunk(png, "IHDR", ihdr);
    pngChunk(png, "IDAT", std::string("\x78\x9c\x03\x00\x00\x00\x00\x01", 8));
    pngChunk(png, "IEND", "");
    return png;
}

// Uncompressed true-colour TGA: an 18-byte header and nothing else.
std::string tgaHeader(std::uint16_t width, std::uint16_t height) {
    std::string tga{0, 0, 2, 0, 0, 0, 0, 0};
    putLE16(tga, 0);
    putLE16(tga, 0);
    putLE16(tga, width);
    putLE16(tga, height);
    tga += char(24);
    tga += char(0);
    return tga;
}

// SGI: the 512-byte header of a verbatim 8-bit RGB image.
std::string sgiHeader(std::uint16_t width, std::uint16_t height) {
    std::string sgi;
    putBE16(sgi, 474);  // magic
    sgi += char(0);     // verbatim
    sgi += char(1);     // 1 byte per channel
    putBE16(sgi, 3);    // dimensions
    putBE16(sgi, width);
    putBE16(sgi, height);
    putBE16(sgi, 3);  // channels
    putBE32(sgi, 0);
    putBE32(sgi, 255);
    sgi.resize(512, '\0');
    return sgi;
}

}  // namespace

TEST(HostileImage, HugePngHeaderIsRefusedBeforeAllocating) {
    test::TempDir dir;
    const std::string path = dir.file("huge.png");
    test::writeText(path, pngHeader(30000, 30000));
    const std::string msg = inputError([&] { readImage(path); });
    EXPECT_THAT(msg, HasSubstr(path + ": 30000 x 30000 pixels exceed the limit"));
    EXPECT_THAT(msg, HasSubstr("--max-image-pixels"));
}

TEST(HostileImage, HugeTgaAndSgiHeadersAreRefusedThroughOpenImageIO) {
    test::TempDir dir;
    const std::string tga = dir.file("huge.tga");
    test::writeText(tga, tgaHeader(30000, 30000));
    EXPECT_THAT(inputError([&] { readImage(tga); }), HasSubstr(tga + ": 30000 x 30000 pixels exceed the limit"));
    const std::string sgi = dir.file("huge.sgi");
    test::writeText(sgi, sgiHeader(30000, 30000));
    EXPECT_THAT(inputError([&] { readImage(sgi); }), HasSubstr(sgi + ": 30000 x 30000 pixels exceed the limit"));
}

TEST(HostileImage, PixelAndDecodedLimitsApplyToExrAndPng) {
    test::TempDir dir;
    const auto img = test::makeImage(16, 16, {"R", "G", "B"}, [](int x, int y, int c) { return float(x + y + c) / 40; });
    for (const char* name : {"a.exr", "a.png"}) {
        const std::string path = dir.file(name);
        writeImage(*img, path);
        const std::uint64_t pixels = limit(Limit::ImagePixels), decoded = limit(Limit::DecodedBytes);
        setLimit(Limit::ImagePixels, 255);
        EXPECT_THAT(inputError([&] { readImage(path); }), HasSubstr(path + ": 16 x 16 pixels exceed the limit of 255"));
        setLimit(Limit::ImagePixels, pixels);
        setLimit(Limit::DecodedBytes, 1000);
        EXPECT_THAT(inputError([&] { readImage(path); }), HasSubstr("--max-decoded-bytes"));
        setLimit(Limit::DecodedBytes, decoded);
        EXPECT_EQ(readImage(path)->width(), 16);
    }
}

TEST(HostileImage, SpecialFilesAreRefusedWithoutBlocking) {
    test::TempDir dir;
    for (const char* name : {"pipe.exr", "pipe.png", "pipe.tif", "pipe.tga"}) {
        const std::string fifo = dir.file(name);
        ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
        EXPECT_THAT(inputError([&] { readImage(fifo); }), HasSubstr("'" + fifo + "': it is a FIFO"));
    }
    EXPECT_THAT(inputError([&] { readImage("/dev/zero"); }), HasSubstr("'/dev/zero': it is a character device"));
    EXPECT_THAT(inputError([&] { readImage(dir.path()); }), HasSubstr("it is a directory"));
}

TEST(HostileColorMap, SpecialFilesAreRefusedWithoutBlocking) {
    test::TempDir dir;
    const std::string fifo = dir.file("map.json");
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_THAT(inputError([&] { loadColorMap(fifo); }), HasSubstr("colour map '" + fifo + "': it is a FIFO"));
    EXPECT_THAT(inputError([&] { loadColorMap("/dev/zero"); }), HasSubstr("'/dev/zero': it is a character device"));
    EXPECT_THAT(inputError([&] { loadColorMap(dir.path()); }), HasSubstr("it is a directory"));
}
