// The threshold table of 8-bit sRGB codes (framework/data/src/io/srgb_code.h)
// gives the bits of the pow it replaces: lround(linearToSrgb(v) * 255).
// Every float in (0, 1) was compared once, outside the suite: 0 of the
// 1,065,353,215 differ (4 s on 2 cores, too long beside a sanitizer). Here
// are the ones where a table can go wrong — each threshold and its
// neighbours, each bucket's edges — and an even spread of the rest.
#include "eight_bit.h"
#include "srgb_code.h"
#include "../../../plugins/normals/tests/simd_targets.h"

#include <darkroom/buffer.h>
#include <darkroom/srgb.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

using darkroom::io::srgbCode;

namespace {

constexpr std::uint32_t kOne = 0x3f800000u;

int expected(std::uint32_t bits) {
    return int(std::lround(darkroom::linearToSrgb(std::bit_cast<float>(bits)) * 255.0f));
}

void expectSame(std::uint32_t bits) {
    if (bits == 0 || bits >= kOne) return;
    ASSERT_EQ(int(srgbCode(std::bit_cast<float>(bits))), expected(bits)) << std::bit_cast<float>(bits);
}

}  // namespace

TEST(SrgbCode, EveryCodeChangesWhereThePowSaysAndNowhereElse) {
    // Where the pow's code steps, by bisection here too: the table must step
    // at the same float, and agree a few floats either side.
    for (int k = 1; k <= 255; ++k) {
        std::uint32_t lo = 1, hi = kOne;
        while (lo < hi) {
            const std::uint32_t mid = lo + (hi - lo) / 2;
            if (expected(mid) >= k) hi = mid;
            else lo = mid + 1;
        }
        for (std::uint32_t d = 0; d < 8; ++d) {
            expectSame(lo + d);
            expectSame(lo - d);
        }
    }
}

TEST(SrgbCode, BucketEdgesAndAnEvenSpreadAgreeWithThePow) {
    for (std::uint32_t b = 0; b <= (kOne >> 16); ++b)
        for (const std::uint32_t d : {0u, 1u, 0xfffeu, 0xffffu}) expectSame((b << 16) + d);
    for (std::uint32_t bits = 1; bits < kOne; bits += 977) expectSame(bits);  // about a million values
    EXPECT_EQ(srgbCode(1e-30f), 0);
    EXPECT_EQ(srgbCode(std::nextafter(1.0f, 0.0f)), 255);
    EXPECT_EQ(srgbCode(0.5f), 188);  // the sRGB code of half linear light
}

// The whole-image encoder (eight_bit.cpp) inlines the table and rounds alpha
// without lround: both must give the codes of the plain formulas, at every
// rounding edge of alpha (k + 0.5) / 255 and its neighbours, every sRGB
// threshold's neighbours, and the special values.
TEST(SrgbCode, TheImageEncoderGivesThePlainFormulasCodes) {
    std::vector<float> values{0.0f, -0.0f, -1.0f, 1.0f, 2.0f, std::nanf(""), INFINITY, -INFINITY, 1e-30f, 0.5f};
    for (int k = 0; k < 255; ++k) {
        float edge = (float(k) + 0.5f) / 255.0f;
        for (int d = 0; d < 4; ++d) edge = std::nextafter(edge, 0.0f);
        for (int d = 0; d < 8; ++d, edge = std::nextafter(edge, 1.0f)) values.push_back(edge);
    }
    for (std::uint32_t bits = 1; bits < kOne; bits += 104729) values.push_back(std::bit_cast<float>(bits));
    const int n = int(values.size());
    auto image = darkroom::makeCpuBuffer(n, 1, {{"Y", darkroom::ChannelType::Float32}, {"A", darkroom::ChannelType::Float32}});
    std::copy(values.begin(), values.end(), image->writeFloat("Y"));
    std::copy(values.begin(), values.end(), image->writeFloat("A"));
    const auto pixels = darkroom::io::encodeEightBit(*image, "test.png", {}, true);
    ASSERT_EQ(pixels.channels, 2);
    const auto plain = [](float v, bool alpha) {
        if (!(v > 0.0f)) return 0;
        if (v >= 1.0f) return 255;
        return alpha ? int(std::lround(v * 255.0f)) : expected(std::bit_cast<std::uint32_t>(v));
    };
    for (int i = 0; i < n; ++i) {
        EXPECT_EQ(int(pixels.data[std::size_t(2 * i)]), plain(values[std::size_t(i)], false)) << values[std::size_t(i)];
        EXPECT_EQ(int(pixels.data[std::size_t(2 * i + 1)]), plain(values[std::size_t(i)], true)) << values[std::size_t(i)];
    }
}

// The encoder skips spans whose every value gives code 0 (background): a
// lone lit value anywhere among them, at a span's first or last place or in
// a row's tail shorter than a span, still gets its code.
TEST(SrgbCode, LitValuesAmongBackgroundKeepTheirCodes) {
    const int w = 101;  // three spans of 32 and a tail of 5
    const float background[] = {0.0f, -0.0f, -2.0f, std::nanf(""), -INFINITY};
    for (int lit : {0, 1, 31, 32, 63, 64, 95, 96, 100}) {
        auto image = darkroom::makeCpuBuffer(w, 2, {{"Y", darkroom::ChannelType::Float32}, {"A", darkroom::ChannelType::Float32}});
        float* y = image->writeFloat("Y");
        float* a = image->writeFloat("A");
        for (int i = 0; i < 2 * w; ++i) y[i] = a[i] = background[i % 5];
        y[w + lit] = 0.5f;   // second row: code 188
        a[lit] = 0.25f;      // first row: alpha lround(63.75) = 64
        const auto px = darkroom::io::encodeEightBit(*image, "test.png", {}, true);
        for (int i = 0; i < 2 * w; ++i) {
            EXPECT_EQ(int(px.data[std::size_t(2 * i)]), i == w + lit ? 188 : 0) << "lit " << lit << ", pixel " << i;
            EXPECT_EQ(int(px.data[std::size_t(2 * i + 1)]), i == lit ? 64 : 0) << "lit " << lit << ", pixel " << i;
        }
    }
}

// The rows are encoded a vector of pixels at a time (eight_bit_rows.cpp):
// grey, grey + alpha, RGB and RGBA rows, of widths with and without a tail
// shorter than a vector, give every value's own code (encodeColourValue,
// encodeAlphaValue) with every SIMD instruction set this CPU has. Values:
// special ones, every sRGB threshold and alpha rounding edge with their
// neighbours, and random ones in and around (0, 1).
TEST(SrgbCode, RowsEncodedByVectorsGiveEachValuesCode) {
    std::vector<float> values{0.0f, -0.0f, -1.0f, 1.0f, 2.0f, std::nanf(""), INFINITY, -INFINITY, 1e-30f, 0.5f};
    const darkroom::io::SrgbCodeTable& table = darkroom::io::srgbCodeTable();
    for (int k = 1; k < 256; ++k) {
        const float t = std::bit_cast<float>(table.threshold[k]);
        values.insert(values.end(), {std::nextafter(t, 0.0f), t, std::nextafter(t, 1.0f)});
        const float edge = (float(k) - 0.5f) / 255.0f;
        values.insert(values.end(), {std::nextafter(edge, 0.0f), edge, std::nextafter(edge, 1.0f)});
    }
    std::mt19937 random(7);
    std::uniform_real_distribution<float> around(-0.25f, 1.25f);
    while (values.size() < 4000) values.push_back(around(random));
    for (int channels = 1; channels <= 4; ++channels)
        for (const bool alpha : {false, true}) {
            if (alpha && channels == 1) continue;
            for (const int width : {1, 15, 16, 37, 1000}) {
                const int height = int(values.size()) / width / channels;
                std::vector<std::vector<float>> planes{std::size_t(channels)};
                darkroom::io::EightBitSource src;
                src.width = width, src.height = height, src.channels = channels, src.alpha = alpha;
                for (int c = 0; c < channels; ++c) {
                    // Each channel a different stretch of the values.
                    planes[std::size_t(c)].assign(values.begin() + c * width * height,
                                                  values.begin() + (c + 1) * width * height);
                    src.planes.push_back(planes[std::size_t(c)].data());
                }
                const std::size_t rowBytes = std::size_t(width * channels);
                const auto results = darkroom::test::resultsPerSimdTarget([&] {
                    std::vector<unsigned char> rows(rowBytes * std::size_t(height), 0x5a);
                    darkroom::io::encodeEightBitRows(src, rows.data(), rowBytes);
                    return rows;
                });
                for (const auto& [target, rows] : results)
                    for (int i = 0; i < width * height; ++i)
                        for (int c = 0; c < channels; ++c) {
                            const float v = planes[std::size_t(c)][std::size_t(i)];
                            const int want = alpha && c == channels - 1 ? darkroom::io::encodeAlphaValue(v)
                                                                        : darkroom::io::encodeColourValue(v);
                            ASSERT_EQ(int(rows[std::size_t(i * channels + c)]), want)
                                << target << ", " << channels << " channels" << (alpha ? " with alpha" : "")
                                << ", width " << width << ", pixel " << i << ", value " << v;
                        }
            }
        }
}
