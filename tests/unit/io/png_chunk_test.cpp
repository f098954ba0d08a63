// A PNG chunk that declares more bytes than the file holds is refused before
// OpenImageIO (libpng) allocates it. Found by the image fuzz harness
// (tests/fuzz): a 200-byte PNG with a tEXt chunk of 1,936,523,284 bytes made
// libpng allocate 1.9 GB while reading the header.
#include "test_support.h"

#include <darkroom/error.h>
#include <darkroom/data/image_io.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

using namespace darkroom;
using ::testing::HasSubstr;

namespace {

void putBE32(std::string& s, std::uint32_t v) {
    for (int b = 3; b >= 0; --b) s += char((v >> (8 * b)) & 0xff);
}

// The signature and a 1 x 1 RGBA IHDR (CRCs are not looked at before the
// allocation, so they are left 0), then `tail`.
std::string pngStart(const std::string& tail) {
    std::string png = "\x89PNG\r\n\x1a\n";
    putBE32(png, 13);
    png += "IHDR";
    putBE32(png, 1);
    putBE32(png, 1);
    png += std::string{8, 6, 0, 0, 0};
    putBE32(png, 0);
    return png + tail;
}

}  // namespace

TEST(PngChunks, ChunkLongerThanTheFileIsRefusedBeforeOpenImageIO) {
    test::TempDir dir;
    const std::string path = dir.file("lying-text.png");
    std::string chunk;
    putBE32(chunk, 1936523284u);
    chunk += "tEXt";
    chunk += "Comment";
    test::writeText(path, pngStart(chunk));
    try {
        readImage(path);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_THAT(e.what(), HasSubstr(path + ": PNG chunk 'tEXt' at byte 33 declares 1936523284 bytes"));
    }
}

TEST(PngChunks, TruncatedLastChunkIsRefusedWhateverTheExtension) {
    test::TempDir dir;
    const std::string path = dir.file("named.tga");  // OpenImageIO would fall back to PNG by content
    std::string chunk;
    putBE32(chunk, 100);
    chunk += "IDAT";
    chunk += "xyz";
    test::writeText(path, pngStart(chunk));
    EXPECT_THROW(readImage(path), InputError);
}
