// The native PNG encoder (framework/data/src/io/png_encoder.h, compiled into
// this test): every filter and level, and the run encoder, decodes back pixel for pixel through
// libpng (which checks every CRC and the zlib stream), for grey, grey+alpha,
// RGB and RGBA; the chunks are those libpng wrote before (IHDR, gAMA, sRGB,
// cHRM with the same bytes, IDAT, IEND); a large image spans several IDATs.
#include "png_encoder.h"
#include "png_up_filter.h"

#include <gtest/gtest.h>
#include <png.h>
#include <zlib.h>

#include <cstdint>
#include <string>
#include <vector>

using namespace darkroom::io;

namespace {

// A smooth gradient with noise in the low bits and a transparent corner
// (what filters and deflate see in a rendered picture), then rows of random
// bytes, so that every filter's arithmetic (wrapping, Paeth's ties) is
// exercised.
std::vector<unsigned char> picture(int w, int h, int channels) {
    std::vector<unsigned char> px(std::size_t(w) * std::size_t(h) * std::size_t(channels));
    std::uint32_t seed = 12345;
    for (std::size_t i = 0; i < px.size(); ++i) {
        seed = seed * 1664525u + 1013904223u;
        const std::size_t pixel = i / std::size_t(channels), x = pixel % std::size_t(w), y = pixel / std::size_t(w);
        const bool clear = x + y < std::size_t(w) / 3, noise = y >= std::size_t(h) / 2;
        px[i] = clear   ? 0
                : noise ? static_cast<unsigned char>(seed >> 24)
                        : static_cast<unsigned char>(x * 7 + y * 3 + (i % std::size_t(channels)) * 50 + (seed >> 30));
    }
    return px;
}

// libpng's simplified reader, in the file's own format: the bytes as stored.
std::vector<unsigned char> decode(const std::string& file, int channels) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_memory(&image, file.data(), file.size())) {
        ADD_FAILURE() << "libpng: " << image.message;
        return {};
    }
    static const png_uint_32 formats[] = {PNG_FORMAT_GRAY, PNG_FORMAT_GA, PNG_FORMAT_RGB, PNG_FORMAT_RGBA};
    image.format = formats[channels - 1];
    std::vector<unsigned char> out(PNG_IMAGE_SIZE(image));
    if (!png_image_finish_read(&image, nullptr, out.data(), 0, nullptr)) ADD_FAILURE() << "libpng: " << image.message;
    return out;
}

struct Chunk {
    std::string type, data;
};

// Walks the chunks, checking each CRC with zlib's crc32.
std::vector<Chunk> chunksOf(const std::string& file) {
    std::vector<Chunk> out;
    auto u32 = [&](std::size_t at) {
        return std::uint32_t(static_cast<unsigned char>(file[at])) << 24 |
               std::uint32_t(static_cast<unsigned char>(file[at + 1])) << 16 |
               std::uint32_t(static_cast<unsigned char>(file[at + 2])) << 8 |
               std::uint32_t(static_cast<unsigned char>(file[at + 3]));
    };
    EXPECT_EQ(file.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
    for (std::size_t at = 8; at + 12 <= file.size();) {
        const std::uint32_t n = u32(at);
        const auto* typeAndData = reinterpret_cast<const Bytef*>(file.data() + at + 4);
        EXPECT_EQ(u32(at + 8 + n), std::uint32_t(crc32(0, typeAndData, uInt(n + 4)))) << "chunk " << out.size();
        out.push_back({file.substr(at + 4, 4), file.substr(at + 8, n)});
        at += 12 + n;
    }
    return out;
}

const PngFilter allFilters[] = {PngFilter::None, PngFilter::Sub, PngFilter::Up, PngFilter::Average, PngFilter::Paeth,
                                PngFilter::Adaptive};

}  // namespace

TEST(PngEncoder, EveryFilterLevelAndLayoutDecodesPixelExact) {
    for (int channels = 1; channels <= 4; ++channels)
        for (auto [w, h] : {std::pair{1, 1}, std::pair{7, 5}, std::pair{33, 17}})
            for (PngFilter f : allFilters)
                for (int level : {0, 1, 6, 12, -1}) {  // -1: the run encoder
                    const auto px = picture(w, h, channels);
                    const PngEncoding e = level < 0 ? PngEncoding{f, 1, Deflater::Runs} : PngEncoding{f, level};
                    const std::string png = encodePng({w, h, channels, px.data()}, e);
                    EXPECT_EQ(decode(png, channels), px) << channels << " channels, " << w << "x" << h << ", filter "
                                                         << int(f) << ", level " << level;
                }
}

TEST(PngEncoder, RowsCarryTheirFilterType) {
    const auto px = picture(9, 4, 3);
    const PngPixels pixels{9, 4, 3, px.data()};
    std::vector<unsigned char> rows(filteredSize(pixels));
    ASSERT_EQ(rows.size(), 4u * (9 * 3 + 1));
    for (PngFilter f : allFilters) {
        filterRows(pixels, f, rows.data());
        for (int y = 0; y < 4; ++y) {
            const int type = rows[std::size_t(y) * 28];
            if (f == PngFilter::Adaptive)
                EXPECT_LE(type, 4);
            else
                EXPECT_EQ(type, int(f));
        }
    }
    // "none" leaves the bytes as they are.
    filterRows(pixels, PngFilter::None, rows.data());
    EXPECT_EQ(std::vector<unsigned char>(rows.begin() + 1, rows.begin() + 28),
              std::vector<unsigned char>(px.begin(), px.begin() + 27));
}

TEST(PngEncoder, ChunksAreThoseLibpngWroteForSrgb) {
    const auto px = picture(6, 3, 4);
    const auto chunks = chunksOf(encodePng({6, 3, 4, px.data()}, {}));
    ASSERT_EQ(chunks.size(), 6u);
    const char* types[] = {"IHDR", "gAMA", "sRGB", "cHRM", "IDAT", "IEND"};
    for (std::size_t i = 0; i < chunks.size(); ++i) EXPECT_EQ(chunks[i].type, types[i]);
    // Width 6, height 3, 8 bits, RGBA, deflate, filter method 0, not interlaced.
    EXPECT_EQ(chunks[0].data, std::string("\0\0\0\x06\0\0\0\x03\x08\x06\0\0\0", 13));
    // As libpng's png_set_sRGB_gAMA_and_cHRM(perceptual) wrote them.
    EXPECT_EQ(chunks[1].data, std::string("\0\0\xb1\x8f", 4));
    EXPECT_EQ(chunks[2].data, std::string("\0", 1));
    EXPECT_EQ(chunks[3].data, std::string("\0\0\x7a\x26\0\0\x80\x84\0\0\xfa\0\0\0\x80\xe8"
                                          "\0\0\x75\x30\0\0\xea\x60\0\0\x3a\x98\0\0\x17\x70",
                                          32));
    EXPECT_TRUE(chunks[5].data.empty());
}

TEST(PngEncoder, LargeImageSpansSeveralIdatChunks) {
    // Level 0 stores: 1024 x 768 RGBA is 3 MiB of deflate, at most 1 MiB per IDAT.
    const auto px = picture(1024, 768, 4);
    const std::string png = encodePng({1024, 768, 4, px.data()}, {PngFilter::Up, 0});
    int idats = 0;
    for (const auto& c : chunksOf(png)) idats += c.type == "IDAT";
    EXPECT_EQ(idats, 4);
    EXPECT_EQ(decode(png, 4), px);
}

// The writer filters in place (png_up_filter.h: bands of 32 rows in
// parallel, SIMD with a scalar tail): the same bytes as filterRows' "up",
// across band edges and at widths that leave tails.
TEST(PngEncoder, UpFilterInPlaceMatchesFilterRows) {
    for (int channels : {1, 3, 4})
        for (int w : {1, 7, 33, 100})
            for (int h : {1, 31, 32, 33, 65, 97}) {
                const auto px = picture(w, h, channels);
                const PngPixels pixels{w, h, channels, px.data()};
                std::vector<unsigned char> expected(filteredSize(pixels)), inPlace(filteredSize(pixels));
                filterRows(pixels, PngFilter::Up, expected.data());
                const std::size_t rowBytes = std::size_t(w) * std::size_t(channels) + 1;
                for (int y = 0; y < h; ++y)
                    std::copy_n(px.data() + std::size_t(y) * (rowBytes - 1), rowBytes - 1, inPlace.data() + std::size_t(y) * rowBytes + 1);
                filterUpInPlace(inPlace.data(), rowBytes, h);
                EXPECT_EQ(inPlace, expected) << channels << " channels, " << w << "x" << h;
            }
}
