// Regressions for the .vti and .npy/.npz readers (issue 18): forged sizes are
// refused from the header before anything is allocated or inflated, special
// files are refused without blocking. Every input is built here.
#include "input_error.h"
#include "test_support.h"

#include <darkroom/error.h>
#include <darkroom/data/formats/npy.h>
#include <darkroom/data/formats/vti.h>
#include <darkroom/limits.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <cstdint>
#include <cstring>
#include <functional>

using namespace darkroom;
using darkroom::test::inputError;
using ::testing::HasSubstr;

namespace {


std::string vti(const std::string& wholeExtent, const std::string& body) {
    return "<VTKFile type=\"ImageData\" version=\"1.0\">\n<ImageData WholeExtent=\"" + wholeExtent +
           "\" Origin=\"0 0 0\" Spacing=\"1 1 1\">\n<Piece Extent=\"" + wholeExtent + "\">\n" + body +
           "</Piece>\n</ImageData>\n</VTKFile>\n";
}

void putU32(std::string& s, std::size_t at, std::uint32_t v) {
    for (int b = 0; b < 4; ++b) s[at + std::size_t(b)] = char((v >> (8 * b)) & 0xff);
}

// Sets the uncompressed size of every member in the local headers and the
// central directory of a small (non-zip64) archive.
std::string withClaimedSize(std::string zip, std::uint32_t size) {
    std::size_t n = 0;
    for (std::size_t at = zip.find("PK\x03\x04"); at != std::string::npos; at = zip.find("PK\x03\x04", at + 4), ++n)
        putU32(zip, at + 22, size);
    for (std::size_t at = zip.find("PK\x01\x02"); at != std::string::npos; at = zip.find("PK\x01\x02", at + 4), ++n)
        putU32(zip, at + 24, size);
    EXPECT_EQ(n, 2u) << "one local header and one central directory entry";
    return zip;
}

}  // namespace

TEST(HostileVti, ExtentsThatOverflowAreRefused) {
    test::TempDir dir;
    const std::string path = dir.file("overflow.vti");
    // x1 - x0 overflows a signed 64-bit integer (undefined behaviour before).
    test::writeText(path, vti("-9223372036854775807 9223372036854775807 0 0 0 0", ""));
    const std::string msg = inputError([&] { readVti(path); });
    EXPECT_THAT(msg, HasSubstr(path + ":2:"));
    EXPECT_THAT(msg, HasSubstr("expected x0 <= x1"));
}

TEST(HostileVti, ImagesBeyondThePixelLimitAreRefusedFromTheHeader) {
    test::TempDir dir;
    const std::string path = dir.file("huge.vti");
    test::writeText(path, vti("0 1048575 0 1048575 0 0", ""));
    const std::string msg = inputError([&] { readVti(path); });
    EXPECT_THAT(msg, HasSubstr(path + ":2: WholeExtent: 1048576 x 1048576 pixels exceed"));
    EXPECT_THAT(msg, HasSubstr("--max-image-pixels"));
}

TEST(HostileVti, ZlibDataLargerThanTheImageIsRefusedBeforeInflating) {
    test::TempDir dir;
    const std::string path = dir.file("bomb.vti");
    // A 2 x 2 image (16 bytes of float32) whose zlib header declares 1 GiB.
    std::string head(12 + 4 * 1024 + 2, '\0');  // a multiple of 3: base64 without padding
    putU32(head, 0, 1024);
    putU32(head, 4, 1u << 20);
    for (std::size_t i = 0; i < 1024; ++i) putU32(head, 12 + 4 * i, 1100);
    static const char* abc = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string b64;
    for (std::size_t i = 0; i + 2 < head.size(); i += 3) {
        const unsigned v = unsigned(std::uint8_t(head[i])) << 16 | unsigned(std::uint8_t(head[i + 1])) << 8 |
                           std::uint8_t(head[i + 2]);
        b64 += {abc[v >> 18], abc[v >> 12 & 63], abc[v >> 6 & 63], abc[v & 63]};
    }
    std::string text = vti("0 1 0 1 0 0", "<PointData>\n<DataArray type=\"Float32\" Name=\"Z\" format=\"binary\">" +
                                              b64 + "</DataArray>\n</PointData>\n");
    text.insert(text.find(" version"), " compressor=\"vtkZLibDataCompressor\"");
    test::writeText(path, text);
    const std::string msg = inputError([&] { readVti(path); });
    EXPECT_THAT(msg, HasSubstr(path + ":5: DataArray 'Z'"));
    EXPECT_THAT(msg, HasSubstr("declares 1073741824 bytes but the array needs at most 16"));
}

TEST(HostileVti, ABlockHeaderNear2To64IsRefusedNotConverted) {
    // Found by the vti fuzz harness: a UInt64 header word of 2^64 - 1 was
    // read through a double and converted to size_t (undefined behaviour).
    test::TempDir dir;
    const std::string path = dir.file("huge-header.vti");
    const std::string b64(32, '/');  // 24 bytes of 0xFF
    std::string text = vti("0 1 0 1 0 0", "<PointData>\n<DataArray type=\"Float32\" Name=\"Z\" format=\"binary\">" +
                                              b64 + "</DataArray>\n</PointData>\n");
    text.insert(text.find(" version"), " header_type=\"UInt64\" compressor=\"vtkZLibDataCompressor\"");
    test::writeText(path, text);
    const std::string msg = inputError([&] { readVti(path); });
    EXPECT_THAT(msg, HasSubstr(path + ":5: DataArray 'Z'"));
    EXPECT_THAT(msg, HasSubstr("a block header declares 1.84467e+19 bytes; expected a byte count"));
}

TEST(HostileVti, DeeplyNestedElementsAreRefused) {
    test::TempDir dir;
    const std::string path = dir.file("deep.vti");
    std::string s = "<VTKFile type=\"ImageData\">";
    for (int i = 0; i < 200000; ++i) s += "<x>";
    test::writeText(path, s);
    const std::string msg = inputError([&] { readVti(path); });
    EXPECT_THAT(msg, HasSubstr(path + ":1: <x> at byte offset"));
    EXPECT_THAT(msg, HasSubstr("expected at most 256"));
}

TEST(HostileVti, SpecialFilesAreRefused) {
    test::TempDir dir;
    const std::string fifo = dir.file("pipe.vti");
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_THAT(inputError([&] { readVti(fifo); }), HasSubstr(fifo + "': it is a FIFO"));
    EXPECT_THAT(inputError([&] { readVti("/dev/zero"); }), HasSubstr("/dev/zero"));
}

TEST(HostileNpy, ShapesWhoseSizeOverflowsAreRefused) {
    std::string header = "{'descr': '<f4', 'fortran_order': False, 'shape': (4294967296, 4294967296, 16), }\n";
    std::string bytes = std::string("\x93NUMPY\x01\x00", 8);
    bytes += char(header.size() & 0xff);
    bytes += char(header.size() >> 8);
    bytes += header;
    const std::string msg = inputError([&] { parseNpyHeader(bytes, "t.npy"); });
    EXPECT_THAT(msg, HasSubstr("t.npy: shape (4294967296, 4294967296, 16) holds more values than can be addressed"));
}

TEST(HostileNpz, MemberSizeInTheZipDirectoryMustMatchItsShape) {
    test::TempDir dir;
    const std::string good = dir.file("good.npz");
    writeNpz(good, {NpyArray{"data", "<f4", {4, 4}, false, std::vector<float>(16, 1.f)}}, true);
    // The zip directory claims 4 GB for a member whose header says 16 floats:
    // reading it whole allocated (and zeroed) the 4 GB first.
    const std::string forged = dir.file("forged.npz");
    test::writeText(forged, withClaimedSize(test::readText(good), 0xFFFFFFF0u));
    const std::string msg = inputError([&] { readNpz(forged); });
    EXPECT_THAT(msg, HasSubstr(forged + ":data.npy: the zip directory gives the member 4294967280 bytes"));
    EXPECT_THAT(msg, HasSubstr("64 bytes of values"));
}

TEST(HostileNpz, MembersBeyondTheDecodedLimitAreRefused) {
    test::TempDir dir;
    const std::string path = dir.file("a.npz");
    writeNpz(path, {NpyArray{"data", "<f4", {64, 64}, false, std::vector<float>(64 * 64, 1.f)}}, true);
    const std::uint64_t saved = limit(Limit::DecodedBytes);
    setLimit(Limit::DecodedBytes, 4096);
    const std::string msg = inputError([&] { readNpz(path); });
    setLimit(Limit::DecodedBytes, saved);
    EXPECT_THAT(msg, HasSubstr(path + ":data.npy: member of"));
    EXPECT_THAT(msg, HasSubstr("--max-decoded-bytes"));
    EXPECT_EQ(readNpz(path).front().values.size(), 64u * 64u);
}

TEST(HostileNpz, SpecialFilesAreRefused) {
    test::TempDir dir;
    const std::string fifo = dir.file("pipe.npz");
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_THAT(inputError([&] { readNpz(fifo); }), HasSubstr(fifo + "': it is a FIFO"));
    EXPECT_THAT(inputError([&] { readNpzHeaders("/dev/zero"); }), HasSubstr("'/dev/zero': it is a character device"));
}
