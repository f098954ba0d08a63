// Mix: exact products, known compositing answers, pass-through, errors.
#include "../../normals/tests/simd_targets.h"
#include "run_node.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

using namespace darkroom;
using namespace darkroom::test;
using ::testing::HasSubstr;

namespace {

// 4x1 colour with Z (last pixel background), A and a scalar.
std::shared_ptr<WritableBuffer> colour() {
    return makeImage(4, 1, {"R", "G", "B", "A", "Z", "value"}, [](int x, int, int c) {
        const float v[6] = {0.3f + 0.1f * x, 0.7f, 0.9f - 0.2f * x, 1.0f, x == 3 ? kInf : 2.0f + x, 5.0f + x};
        return v[c];
    });
}

std::shared_ptr<WritableBuffer> factor(const std::string& name, const std::vector<float>& f) {
    return makeImage(int(f.size()), 1, {name}, [&](int x, int, int) { return f[std::size_t(x)]; });
}

}  // namespace

TEST(Mix, MultiplyByAFactorChannelGivesExactProducts) {
    const auto img = colour();
    const std::vector<float> ao = {0.0f, 0.25f, 0.37f, 0.5f};
    const BufferPtr out = runImage("Mix", {{"image", {Value(BufferPtr(img))}}, {"other", {Value(BufferPtr(factor("AO", ao)))}}});
    EXPECT_EQ(out->channelNames(), img->channelNames());
    for (int x = 0; x < 3; ++x)
        for (const char* c : {"R", "G", "B"}) EXPECT_EQ(out->hostFloat(c)[x], img->hostFloat(c)[x] * ao[std::size_t(x)]) << c << x;
    // Background (Z = +inf) is left alone by a lighting term.
    for (const char* c : {"R", "G", "B"}) EXPECT_EQ(out->hostFloat(c)[3], img->hostFloat(c)[3]);
    for (const char* c : {"A", "Z", "value"})
        for (int x = 0; x < 4; ++x) EXPECT_EQ(out->hostFloat(c)[x], img->hostFloat(c)[x]) << c;
}

TEST(Mix, MultiplyTakesTheFactorFromTheImageItselfAndHonoursAmount) {
    auto img = makeImage(3, 1, {"R", "G", "B", "SSDD"}, [](int x, int, int c) {
        return c == 3 ? (x == 2 ? kNaN : 0.5f) : 0.8f;
    });
    const BufferPtr out = runImage("Mix", {{"image", {Value(BufferPtr(img))}}, {"factorChannel", {Value("SSDD")}},
                                           {"amount", {Value(0.5)}}});
    EXPECT_EQ(out->hostFloat("R")[0], 0.8f * 0.75f);  // mix(1, 0.5, 0.5) = 0.75
    EXPECT_EQ(out->hostFloat("R")[2], 0.8f);          // NaN factor: no data, no change
    const BufferPtr none = runImage("Mix", {{"image", {Value(BufferPtr(img))}}, {"factorChannel", {Value("SSDD")}},
                                            {"amount", {Value(0.0)}}});
    EXPECT_EQ(none->hostFloat("G")[1], 0.8f);
}

TEST(Mix, OverWithAlphaZeroOneAndHalf) {
    auto base = makeImage(4, 1, {"R", "G", "B", "A"}, [](int x, int, int c) {
        return c == 3 ? (x == 3 ? 0.5f : 1.0f) : 0.25f;
    });
    auto top = makeImage(4, 1, {"R", "G", "B", "A"}, [](int x, int, int c) {
        const float a[4] = {0.0f, 1.0f, 0.5f, 0.5f};
        return c == 3 ? a[x] : (x == 0 ? kNaN : 0.75f);  // NaN colour under zero alpha must not leak
    });
    const BufferPtr out = runImage("Mix", {{"image", {Value(BufferPtr(base))}}, {"other", {Value(BufferPtr(top))}},
                                           {"mode", {Value("over")}}});
    const float* R = out->hostFloat("R");
    const float* A = out->hostFloat("A");
    EXPECT_EQ(R[0], 0.25f);  // alpha 0: the image
    EXPECT_EQ(A[0], 1.0f);
    EXPECT_EQ(R[1], 0.75f);  // alpha 1: the other
    EXPECT_EQ(A[1], 1.0f);
    EXPECT_EQ(R[2], 0.5f);   // half over opaque: the average
    EXPECT_EQ(A[2], 1.0f);
    // Half over half: alpha 0.75, colour (0.5*0.75 + 0.25*0.25) / 0.75 (straight alpha).
    EXPECT_FLOAT_EQ(A[3], 0.75f);
    EXPECT_FLOAT_EQ(R[3], (0.5f * 0.75f + 0.25f * 0.25f) / 0.75f);
}

TEST(Mix, BlendAndAdd) {
    auto a = makeImage(1, 1, {"R", "G", "B", "A"}, [](int, int, int c) { return c == 3 ? 1.0f : 0.5f; });
    auto b = makeImage(1, 1, {"R", "G", "B", "A"}, [](int, int, int c) { return c == 3 ? 0.0f : 0.25f; });
    const BufferPtr blend = runImage("Mix", {{"image", {Value(BufferPtr(a))}}, {"other", {Value(BufferPtr(b))}},
                                             {"mode", {Value("blend")}}, {"amount", {Value(0.25)}}});
    EXPECT_EQ(blend->hostFloat("R")[0], 0.75f * 0.5f + 0.25f * 0.25f);
    EXPECT_EQ(blend->hostFloat("A")[0], 0.75f);
    const BufferPtr add = runImage("Mix", {{"image", {Value(BufferPtr(a))}}, {"other", {Value(BufferPtr(b))}},
                                           {"mode", {Value("add")}}, {"amount", {Value(0.5)}}});
    EXPECT_EQ(add->hostFloat("G")[0], 0.625f);
    EXPECT_EQ(add->hostFloat("A")[0], 1.0f);
}

TEST(Mix, ErrorsNameWhatIsMissing) {
    const BufferPtr img = colour();
    EXPECT_THAT(errorOf("Mix", {{"image", {Value(img)}}}), HasSubstr("'AO'"));
    EXPECT_THAT(errorOf("Mix", {{"image", {Value(img)}}}), HasSubstr("R, G, B, A, Z, value"));
    EXPECT_THAT(errorOf("Mix", {{"image", {Value(img)}}, {"mode", {Value("over")}}}), HasSubstr("'other'"));
    const BufferPtr small = factor("AO", {1.0f, 1.0f});
    const std::string size = errorOf("Mix", {{"image", {Value(img)}}, {"other", {Value(small)}}});
    EXPECT_THAT(size, HasSubstr("4x1"));
    EXPECT_THAT(size, HasSubstr("2x1"));
}

// Mix runs vectors of pixels with the best SIMD instructions of the CPU:
// every instruction set gives the same bits in every mode, with NaN, ±inf,
// transparent and out-of-range values in both images.
TEST(Mix, ResultDoesNotDependOnTheSimdInstructionSet) {
    auto image = [](int seed) {
        return makeImage(53, 7, {"R", "G", "B", "A", "Z", "value"}, [seed](int x, int y, int c) {
            const std::uint32_t h = std::uint32_t(x) * 73856093u ^ std::uint32_t(y) * 19349663u ^ (std::uint32_t(seed) * 83492791u + std::uint32_t(c));
            if (h % 23 == 0) return kNaN;
            if (h % 29 == 0) return h % 2 ? kInf : -kInf;
            if (c == 3) return float(h % 9) * 0.15f - 0.1f;  // alpha below 0, 0, between, above 1
            return float(h % 1000) * 0.002f - 0.2f;
        });
    };
    const BufferPtr a = image(1), b = image(2);
    for (const char* mode : {"multiply", "blend", "over", "add"})
        for (const double amount : {0.35, 1.0}) {
            const Inputs in{{"image", {Value(a)}},          {"other", {Value(b)}},          {"mode", {Value(mode)}},
                            {"factorChannel", {Value("value")}}, {"amount", {Value(amount)}}};
            const auto results = resultsPerSimdTarget([&] { return runImage("Mix", in); });
            for (const auto& [target, out] : results)
                EXPECT_TRUE(identical(*out, *results.front().second))
                    << mode << " " << amount << ": " << target << " differs from " << results.front().first;
        }
}
