// sameBytes, the evaluator's check that a recomputed plane is bit for bit the
// one it replaces: its probes only shorten the answer "different"; a single
// differing byte anywhere, probed or not, still makes two planes different.
#include "same_bytes.h"

#include <gtest/gtest.h>

#include <vector>

using darkroom::sameBytes;

TEST(SameBytes, EqualPlanesAreTheSame) {
    std::vector<unsigned char> a(1 << 20), b;
    for (std::size_t i = 0; i < a.size(); ++i) a[i] = static_cast<unsigned char>(i * 2654435761u >> 13);
    b = a;
    EXPECT_TRUE(sameBytes(a.data(), b.data(), a.size()));
    EXPECT_TRUE(sameBytes(a.data(), b.data(), 0));
}

// The probes find a difference confined to a band of columns away from the
// picture's edge (an object in the middle of a 2048-wide picture), as they
// must for the shortcut to pay: probes at one place per stretch of whole
// rows would all fall in the same columns and miss it.
TEST(SameBytes, ProbesFindADifferenceInABandOfColumns) {
    const std::size_t width = 2048, height = 256;
    std::vector<float> a(width * height, 0.0f), b = a;
    for (std::size_t y = 0; y < height; ++y)
        for (std::size_t x = 900; x < 1000; ++x) b[y * width + x] = 1.0f;
    EXPECT_TRUE(darkroom::probesDiffer(a.data(), b.data(), a.size() * 4));
    EXPECT_FALSE(sameBytes(a.data(), b.data(), a.size() * 4));
    EXPECT_FALSE(darkroom::probesDiffer(b.data(), std::vector<float>(b).data(), b.size() * 4));
}

TEST(SameBytes, AnyOneDifferingByteMakesThemDifferent) {
    // Small and large sizes (below and above the size that is probed), and
    // every position class: the first and last bytes, probed stretches and
    // the bytes between probes.
    for (std::size_t size : {std::size_t(1), std::size_t(100), std::size_t(4096), std::size_t(1) << 20,
                             (std::size_t(1) << 20) + 7}) {
        const std::vector<unsigned char> a(size, 0);
        // (size / 1024 * 7 + size / 2048: inside the 8th probe of a probed size.)
        std::vector<std::size_t> where = {0, size - 1, size / 2, size / 3, size / 64 + 1, size / 1024 * 7 + size / 2048};
        for (std::size_t at : where) {
            if (at >= size) continue;
            std::vector<unsigned char> b = a;
            b[at] = 1;
            EXPECT_FALSE(sameBytes(a.data(), b.data(), size)) << "size " << size << ", byte " << at;
        }
    }
}
