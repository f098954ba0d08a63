// The PNG writer's run encoder (framework/data/src/io/run_deflate.h, compiled
// into this test): whatever the bytes, zlib's own inflate gives them back
// (it checks the block headers, the codes' completeness and the Adler-32);
// runs shrink as a run encoder's should; the Huffman codes it builds are
// complete and within their length limit.
#include "huffman_lengths.h"
#include "run_deflate.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdint>
#include <vector>

using namespace darkroom::io;

namespace {

std::vector<unsigned char> inflated(const std::vector<unsigned char>& z, std::size_t expected) {
    std::vector<unsigned char> out(expected + 16);
    uLongf size = uLongf(out.size());
    const int rc = uncompress(out.data(), &size, z.data(), uLong(z.size()));
    EXPECT_EQ(rc, Z_OK);
    out.resize(rc == Z_OK ? size : 0);
    return out;
}

void expectRoundTrip(const std::vector<unsigned char>& data, int pixelBytes, const char* what) {
    const auto z = runDeflateZlib(data.data(), data.size(), pixelBytes);
    EXPECT_EQ(inflated(z, data.size()), data) << what << ", " << data.size() << " bytes, pixel " << pixelBytes;
}

std::uint32_t next(std::uint32_t& seed) { return seed = seed * 1664525u + 1013904223u; }

// Runs of random length and byte, repeated pixels, and noise, mixed: every
// path of the encoder (literal, byte run, pixel run, both, stored block).
std::vector<unsigned char> mixed(std::size_t size, std::uint32_t seed) {
    std::vector<unsigned char> d;
    d.reserve(size);
    while (d.size() < size) {
        const std::uint32_t kind = next(seed) >> 30, n = 1 + (next(seed) >> 22);
        for (std::uint32_t i = 0; i < n && d.size() < size; ++i) {
            if (kind == 0) d.push_back(static_cast<unsigned char>(next(seed) >> 24));
            else if (kind == 1) d.push_back(static_cast<unsigned char>(n));
            else d.push_back(d.size() >= 4 ? d[d.size() - 4] : 7);
        }
    }
    return d;
}

double kraftSum(const HuffmanCode& c) {
    double s = 0;
    for (auto l : c.lengths)
        if (l) s += 1.0 / double(std::uint64_t(1) << l);
    return s;
}

}  // namespace

TEST(RunDeflate, EverySizeAndPixelWidthInflatesBack) {
    for (std::size_t size : {std::size_t(0), std::size_t(1), std::size_t(3), std::size_t(4), std::size_t(259),
                             std::size_t(65535), std::size_t(65536), std::size_t(3) * 131072 + 5})
        for (int pixelBytes = 1; pixelBytes <= 8; ++pixelBytes)
            expectRoundTrip(mixed(size, std::uint32_t(size) * 31u + std::uint32_t(pixelBytes)), pixelBytes, "mixed");
}

TEST(RunDeflate, NoiseIsStoredAndRunsCrossBlocks) {
    std::uint32_t seed = 99;
    std::vector<unsigned char> noise(300000);
    for (auto& b : noise) b = static_cast<unsigned char>(next(seed) >> 24);
    const auto z = runDeflateZlib(noise.data(), noise.size(), 4);
    // Stored blocks: 5 bytes per 65,535 and the zlib frame, nothing more.
    EXPECT_LE(z.size(), noise.size() + 5 * (noise.size() / 65535 + 3) + 6);
    EXPECT_EQ(inflated(z, noise.size()), noise);
    // One run of a million bytes spans eight blocks of the encoder.
    std::vector<unsigned char> run(1000000, 0xab);
    run[0] = 1;
    const auto zr = runDeflateZlib(run.data(), run.size(), 3);
    EXPECT_LT(zr.size(), 5000u);  // 258 bytes per length/distance pair of a few bits
    EXPECT_EQ(inflated(zr, run.size()), run);
}

TEST(RunDeflate, RepeatedPixelsUseThePixelDistance) {
    // RGBA pixels cycling with period 4 bytes: no byte repeats its neighbour,
    // every pixel repeats the one before it.
    std::vector<unsigned char> px;
    for (int i = 0; i < 100000; ++i) px.insert(px.end(), {10, 200, 30, 255});
    const auto z = runDeflateZlib(px.data(), px.size(), 4);
    EXPECT_LT(z.size(), 2000u);
    EXPECT_EQ(inflated(z, px.size()), px);
}

TEST(HuffmanCode, CompleteAndWithinTheLimit) {
    // Fibonacci frequencies give Huffman's deepest tree (one more level per
    // symbol): 30 symbols would need 29 bits without the limit.
    std::vector<std::uint32_t> fib(30);
    fib[0] = fib[1] = 1;
    for (std::size_t i = 2; i < fib.size(); ++i) fib[i] = fib[i - 1] + fib[i - 2];
    for (int limit : {7, 15}) {
        const HuffmanCode c = huffmanCode(fib.data(), int(fib.size()), limit);
        for (auto l : c.lengths) EXPECT_LE(int(l), limit);
        EXPECT_DOUBLE_EQ(kraftSum(c), 1.0) << "limit " << limit;
    }
    // One symbol used, or none: two codes of one bit, still a complete code.
    std::vector<std::uint32_t> one(19, 0);
    one[5] = 42;
    const HuffmanCode c1 = huffmanCode(one.data(), 19, 7);
    EXPECT_EQ(c1.lengths[5], 1);
    EXPECT_DOUBLE_EQ(kraftSum(c1), 1.0);
    const std::vector<std::uint32_t> none(30, 0);
    EXPECT_DOUBLE_EQ(kraftSum(huffmanCode(none.data(), 30, 15)), 1.0);
}

TEST(HuffmanCode, CanonicalCodesArePrefixFree) {
    const std::uint32_t f[8] = {5, 9, 12, 13, 16, 45, 0, 1};
    const HuffmanCode c = huffmanCode(f, 8, 15);
    for (int a = 0; a < 8; ++a)
        for (int b = 0; b < 8; ++b) {
            if (a == b || !c.lengths[std::size_t(a)] || !c.lengths[std::size_t(b)]) continue;
            const int la = c.lengths[std::size_t(a)], lb = c.lengths[std::size_t(b)];
            if (la > lb) continue;
            // Codes are stored bit-reversed: a prefix is a match in the low bits.
            const std::uint32_t mask = (1u << la) - 1u;
            EXPECT_NE(c.codes[std::size_t(a)] & mask, c.codes[std::size_t(b)] & mask) << a << " prefixes " << b;
        }
}

// The blocks are coded in parallel and joined at the bit where each lands:
// coded blocks of every bit length after one another, and stored blocks
// (which align to a byte of the whole stream) between coded ones, inflate
// back, and coding the same bytes twice gives the same stream.
TEST(RunDeflate, BlocksCodedApartJoinIntoOneStream) {
    constexpr std::size_t kBlock = std::size_t(1) << 17;
    std::uint32_t seed = 5;
    std::vector<unsigned char> data;
    for (int k = 0; k < 7; ++k) {
        const bool noise = k % 3 == 1;  // stored between coded blocks
        const auto part = noise ? std::vector<unsigned char>(kBlock) : mixed(kBlock - std::size_t(k) * 11, seed + k);
        const std::size_t at = data.size();
        data.insert(data.end(), part.begin(), part.end());
        if (noise)
            for (std::size_t i = at; i < data.size(); ++i) data[i] = static_cast<unsigned char>(next(seed) >> 24);
    }
    for (int pixelBytes : {1, 3, 4}) {
        expectRoundTrip(data, pixelBytes, "coded and stored blocks");
        EXPECT_EQ(runDeflateZlib(data.data(), data.size(), pixelBytes),
                  runDeflateZlib(data.data(), data.size(), pixelBytes));
    }
}
