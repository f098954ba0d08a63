// The direct EXR decoder (framework/data/src/io/exr_direct.h) against
// OpenEXR's C++ library on the same files: the pixels must be the same bit
// for bit (NaN payloads included) wherever the direct decoder takes a file,
// and the files it does not take must read as before. The reader is compiled
// into this test (tests/CMakeLists.txt) to call both paths.
#include "test_support.h"

#include "exr_direct.h"
#include "exr_file.h"
#include "exr_zip.h"

#include <darkroom/error.h>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfTiledOutputFile.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

using namespace darkroom;

namespace {

struct Channel {
    std::string name;
    Imf::PixelType type;
};

struct FileSpec {
    int width = 37, height = 45;
    Imath::V2i origin{0, 0};        // the data window's top-left corner
    Imath::Box2i display{{0, 0}, {-1, -1}};  // empty: the data window
    Imf::Compression compression = Imf::ZIP_COMPRESSION;
    std::vector<Channel> channels{{"Z", Imf::FLOAT}, {"height", Imf::FLOAT}};
    bool tiled = false;
};

// Samples smooth enough to compress, with specials (NaN with payloads,
// infinities, denormals, -0) and a band of random bits that does not.
std::uint32_t floatSample(int x, int y, int c, std::mt19937& rng) {
    if (y % 7 == 3 && x % 3 == 0) return rng();
    static const std::uint32_t specials[] = {0x7fc00000u, 0x7fa12345u, 0xffc00001u, 0x7f800000u,
                                             0xff800000u, 0x00000001u, 0x80000000u};
    if ((x * 13 + y * 7 + c) % 29 == 0) return specials[(x + y) % 7];
    const float v = float(x) * 0.25f + float(y) * 0.5f + float(c);
    std::uint32_t bits;
    std::memcpy(&bits, &v, 4);
    return bits;
}
std::uint16_t halfSample(int x, int y, int c, std::mt19937& rng) {
    if ((x * 5 + y * 11 + c) % 23 == 0) return std::uint16_t(0x7c01u + (x % 512));  // NaNs with payloads
    if (y % 5 == 2 && x % 4 == 1) return std::uint16_t(rng());
    return std::uint16_t(0x3c00u + ((x + 3 * y + c) & 0x3ff));
}

// The file, written with OpenEXR's C++ library.
void writeFile(const std::string& path, const FileSpec& spec) {
    const Imath::Box2i data(spec.origin, spec.origin + Imath::V2i(spec.width - 1, spec.height - 1));
    Imf::Header header(spec.display.isEmpty() ? data : spec.display, data);
    header.compression() = spec.compression;
    std::mt19937 rng(42);
    const std::size_t pixels = std::size_t(spec.width) * spec.height;
    std::vector<std::vector<std::uint32_t>> planes;
    planes.reserve(spec.channels.size());
    Imf::FrameBuffer fb;
    const std::ptrdiff_t origin = std::ptrdiff_t(spec.origin.x) + std::ptrdiff_t(spec.origin.y) * spec.width;
    for (std::size_t c = 0; c < spec.channels.size(); ++c) {
        const Channel& ch = spec.channels[c];
        header.channels().insert(ch.name, Imf::Channel(ch.type));
        auto& plane = planes.emplace_back(pixels);
        const std::size_t size = ch.type == Imf::HALF ? 2 : 4;
        auto* bytes = reinterpret_cast<char*>(plane.data());
        for (int y = 0; y < spec.height; ++y)
            for (int x = 0; x < spec.width; ++x) {
                const std::size_t i = std::size_t(y) * spec.width + x;
                if (ch.type == Imf::HALF) {
                    const std::uint16_t h = halfSample(x, y, int(c), rng);
                    std::memcpy(bytes + i * 2, &h, 2);
                } else {
                    plane[i] = floatSample(x, y, int(c), rng);
                }
            }
        fb.insert(ch.name, Imf::Slice(ch.type, bytes - origin * std::ptrdiff_t(size), size, size * spec.width));
    }
    if (spec.tiled) {
        header.setTileDescription(Imf::TileDescription(16, 16, Imf::ONE_LEVEL));
        Imf::TiledOutputFile file(path.c_str(), header);
        file.setFrameBuffer(fb);
        file.writeTiles(0, file.numXTiles() - 1, 0, file.numYTiles() - 1);
    } else {
        Imf::OutputFile file(path.c_str(), header);
        file.setFrameBuffer(fb);
        file.writePixels(spec.height);
    }
}

// Both readers give the same buffer: channels, types, size and every plane's bytes.
void expectSamePixels(const std::string& path) {
    const auto direct = io::readExr(path);
    const auto openExr = io::readExr(path, io::ExrPixelPath::OpenExrOnly);
    ASSERT_EQ(direct->width(), openExr->width());
    ASSERT_EQ(direct->height(), openExr->height());
    ASSERT_EQ(direct->channels().size(), openExr->channels().size());
    for (std::size_t c = 0; c < direct->channels().size(); ++c) {
        const auto& ch = openExr->channels()[c];
        ASSERT_EQ(direct->channels()[c].name, ch.name);
        ASSERT_EQ(direct->channels()[c].type, ch.type);
        const void* a = ch.type == ChannelType::UInt32 ? static_cast<const void*>(direct->hostUInt(ch.name))
                                                        : static_cast<const void*>(direct->hostFloat(ch.name));
        const void* b = ch.type == ChannelType::UInt32 ? static_cast<const void*>(openExr->hostUInt(ch.name))
                                                        : static_cast<const void*>(openExr->hostFloat(ch.name));
        EXPECT_EQ(std::memcmp(a, b, direct->pixelCount() * 4), 0) << path << ": " << ch.name;
    }
    EXPECT_EQ(direct->metadata().camera.has_value(), openExr->metadata().camera.has_value());
}

// Whether the direct decoder takes the file (into a buffer laid out as readExr lays it out).
bool directTakes(const std::string& path) {
    const auto reference = io::readExr(path, io::ExrPixelPath::OpenExrOnly);
    auto buffer = makeCpuBuffer(reference->width(), reference->height(), reference->channels());
    const Imf::InputFile file(path.c_str());
    return io::readExrDirect(path, file.header(), *buffer);
}

std::string compressionName(Imf::Compression c) {
    return c == Imf::ZIP_COMPRESSION ? "zip" : c == Imf::ZIPS_COMPRESSION ? "zips" : c == Imf::NO_COMPRESSION ? "none" : "other";
}

// Every width and height here, each compression the direct decoder takes.
void expectDirectAndSame(FileSpec spec, const std::vector<std::pair<int, int>>& sizes) {
    test::TempDir dir;
    for (Imf::Compression c : {Imf::ZIP_COMPRESSION, Imf::ZIPS_COMPRESSION, Imf::NO_COMPRESSION})
        for (const auto& [w, h] : sizes) {
            spec.compression = c;
            spec.width = w;
            spec.height = h;
            const std::string path =
                dir.file(compressionName(c) + "_" + std::to_string(w) + "x" + std::to_string(h) + ".exr");
            writeFile(path, spec);
            EXPECT_TRUE(directTakes(path)) << path;
            expectSamePixels(path);
        }
}

const std::vector<std::pair<int, int>> kSizes = {{1, 1}, {1, 40}, {37, 45}, {64, 16}, {257, 33}, {300, 17}};

// The zip pre-pass as OpenEXR's writer applies it (the file layout
// document): split into even and odd bytes, then each byte's difference to
// the one before, plus 128.
std::vector<std::uint8_t> applyZipPrepass(const std::vector<std::uint8_t>& raw) {
    std::vector<std::uint8_t> t(raw.size());
    std::size_t even = 0, odd = (raw.size() + 1) / 2;
    for (std::size_t i = 0; i < raw.size(); ++i) t[i % 2 == 0 ? even++ : odd++] = raw[i];
    for (std::size_t i = t.size(); i-- > 1;) t[i] = std::uint8_t(t[i] - t[i - 1] + 128);
    return t;
}

}  // namespace

TEST(ExrZipPrepass, UndoesWhatTheWriterDoes) {
    std::mt19937 rng(7);
    std::vector<std::size_t> sizes;
    for (std::size_t n = 0; n < 140; ++n) sizes.push_back(n);  // each tail of the 16-byte steps, twice over
    for (std::size_t n : {4095u, 4096u, 65537u}) sizes.push_back(n);
    for (std::size_t n : sizes) {
        std::vector<std::uint8_t> raw(n);
        for (auto& b : raw) b = std::uint8_t(rng());
        const auto prepared = applyZipPrepass(raw);
        std::vector<std::uint8_t> back(n);
        io::undoZipPrepass(prepared.data(), n, back.data());
        EXPECT_EQ(back, raw) << n << " bytes";
    }
}

TEST(ExrDirect, FloatPixelsAreThoseOfOpenExrForEveryWidth) { expectDirectAndSame(FileSpec{}, kSizes); }

TEST(ExrDirect, HalfAndUintPixelsAreThoseOfOpenExr) {
    FileSpec spec;
    spec.channels = {{"A", Imf::HALF}, {"B", Imf::HALF}, {"G", Imf::HALF}, {"R", Imf::HALF},
                     {"Z", Imf::FLOAT}, {"id", Imf::UINT}, {"normal.x", Imf::HALF}};
    expectDirectAndSame(spec, kSizes);
}

TEST(ExrDirect, DataWindowAwayFromTheDisplayWindow) {
    FileSpec spec;
    spec.origin = {-13, 21};
    spec.display = Imath::Box2i({0, 0}, {99, 99});
    expectDirectAndSame(spec, {{1, 3}, {50, 37}});
}

TEST(ExrDirect, OtherCompressionsAndTilesReadAsBefore) {
    test::TempDir dir;
    FileSpec spec;
    spec.width = 70;
    spec.height = 41;
    for (Imf::Compression c : {Imf::PIZ_COMPRESSION, Imf::RLE_COMPRESSION, Imf::PXR24_COMPRESSION}) {
        spec.compression = c;
        const std::string path = dir.file("c" + std::to_string(int(c)) + ".exr");
        writeFile(path, spec);
        EXPECT_FALSE(directTakes(path)) << path;
        expectSamePixels(path);
    }
    spec.compression = Imf::ZIP_COMPRESSION;
    spec.tiled = true;
    const std::string tiled = dir.file("tiled.exr");
    writeFile(tiled, spec);
    EXPECT_FALSE(directTakes(tiled));
    expectSamePixels(tiled);
}

// A damaged file reads as it did before the direct decoder: the same pixels,
// or the same error, whatever byte is changed.
TEST(ExrDirect, DamagedChunksFallBackToOpenExr) {
    test::TempDir dir;
    FileSpec spec;
    spec.width = 40;
    spec.height = 40;
    const std::string good = dir.file("good.exr");
    writeFile(good, spec);
    std::ifstream in(good, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string path = dir.file("bad.exr");
    for (std::size_t at = bytes.size() / 3; at < bytes.size(); at += 97) {
        std::string bad = bytes;
        bad[at] = char(bad[at] ^ 0x5a);
        std::ofstream(path, std::ios::binary | std::ios::trunc) << bad;
        std::string direct, openExr;
        try {
            io::readExr(path);
        } catch (const Error& e) {
            direct = e.what();
        }
        try {
            io::readExr(path, io::ExrPixelPath::OpenExrOnly);
        } catch (const Error& e) {
            openExr = e.what();
        }
        EXPECT_EQ(direct, openExr) << "byte " << at;
        if (openExr.empty()) expectSamePixels(path);
    }
}

// The Core API can rebuild a broken offset table by scanning for chunks,
// where the C++ library reads what the table says: the direct decoder must
// not read chunks the C++ library would not (found by the exr fuzz harness:
// a table entry 5 bytes short of its chunk). A broken table goes to the C++
// library.
TEST(ExrDirect, BrokenOffsetTableGoesToOpenExr) {
    test::TempDir dir;
    FileSpec spec;
    spec.width = 4;
    spec.height = 3;  // one ZIP chunk: one table entry, just before the chunk
    const std::string good = dir.file("good.exr");
    writeFile(good, spec);
    std::ifstream in(good, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::size_t table = 0;
    for (std::size_t p = 8; p + 8 <= bytes.size() && table == 0; ++p) {
        std::uint64_t v = 0;
        std::memcpy(&v, bytes.data() + p, 8);
        if (v == p + 8) table = p;
    }
    ASSERT_NE(table, 0u);
    ASSERT_TRUE(directTakes(good));
    for (std::uint64_t entry : {std::uint64_t(table + 8 - 5), std::uint64_t(table + 9), std::uint64_t(0),
                                std::uint64_t(bytes.size()), ~std::uint64_t(0)}) {
        std::string bad = bytes;
        std::memcpy(bad.data() + table, &entry, 8);
        const std::string path = dir.file("bad.exr");
        std::ofstream(path, std::ios::binary | std::ios::trunc) << bad;
        bool openExrReads = true;
        try {
            io::readExr(path, io::ExrPixelPath::OpenExrOnly);
        } catch (const Error&) {
            openExrReads = false;
        }
        if (openExrReads) {
            EXPECT_FALSE(directTakes(path)) << "table entry " << entry;
        }
    }
}
