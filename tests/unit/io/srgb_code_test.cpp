// The threshold table of 8-bit sRGB codes (framework/data/src/io/srgb_code.h)
// gives the bits of the pow it replaces: lround(linearToSrgb(v) * 255).
// Every float in (0, 1) was compared once, outside the suite: 0 of the
// 1,065,353,215 differ (4 s on 2 cores, too long beside a sanitizer). Here
// are the ones where a table can go wrong — each threshold and its
// neighbours, each bucket's edges — and an even spread of the rest.
#include "srgb_code.h"

#include <darkroom/srgb.h>

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>

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
