// FXAA on stress inputs: NaN, transparent and infinite pixels, tiny and empty
// images, every preset, thread counts, pass-through channels, bad input.
#include "../../normals/tests/simd_targets.h"
#include "fxaa_helpers.h"

#include <darkroom/error.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>

using namespace darkroom;
using namespace darkroom::test;
using ::testing::HasSubstr;

namespace {

// A diagonal staircase with some noise: edges everywhere, in both directions.
float busy(int x, int y) {
    const std::uint32_t hsh = std::uint32_t(x) * 73856093u ^ std::uint32_t(y) * 19349663u;
    return ((x + 2 * y) / 5 % 2 ? 0.9f : 0.05f) + 0.05f * float(hsh % 7u) / 7.0f;
}

std::vector<std::string> allPresets() {
    return {"10", "11", "12", "13", "14", "15", "20", "21", "22", "23", "24", "25", "26", "27", "28", "29", "39"};
}

}  // namespace

TEST(FxaaRobustness, ANanPixelStaysPutAndNeverSpreads) {
    // Flat grey with a NaN pixel: the NaN brings no contrast, so nothing changes.
    auto flat = greyImage(7, 7, [](int x, int y) { return x == 3 && y == 3 ? kNaN : 0.5f; }, true);
    EXPECT_TRUE(identical(*runFxaa(flat), *flat));

    // A NaN pixel right beside a step: still NaN, everything else finite.
    auto step = greyImage(12, 9, [](int x, int y) { return x == 6 && y == 4 ? kNaN : (x < 6 ? 0.0f : 1.0f); }, true);
    const BufferPtr out = runFxaa(step);
    for (int y = 0; y < 9; ++y)
        for (int x = 0; x < 12; ++x)
            for (const char* c : {"R", "G", "B", "A"}) {
                const float v = at(*out, c, x, y);
                if (x == 6 && y == 4 && c[0] != 'A')
                    EXPECT_TRUE(std::isnan(v));
                else
                    EXPECT_TRUE(std::isfinite(v) && v >= 0.0f && v <= 1.0f) << c << " " << x << "," << y;
            }
    // Its row neighbours see it as equal to themselves: their cross is flat,
    // so they keep their colour exactly, where without the NaN they would blend.
    EXPECT_EQ(at(*out, "G", 5, 4), 0.0f);
    EXPECT_EQ(at(*out, "G", 7, 4), 1.0f);
    EXPECT_GT(at(*out, "G", 5, 2), 0.0f);  // the step further up is anti-aliased
}

TEST(FxaaRobustness, TransparentPixelsNeitherChangeNorLeakTheirColour) {
    // Left: transparent with red left-overs under it; right: opaque grey.
    auto img = makeImage(10, 6, {"R", "G", "B", "A"}, [](int x, int, int c) {
        if (x < 5) return c == 0 ? 1.0f : 0.0f;  // (1, 0, 0, 0)
        return c == 3 ? 1.0f : 0.2f;
    });
    EXPECT_TRUE(identical(*runFxaa(img), *img));

    // An opaque step next to a transparent region: the step is anti-aliased,
    // no red appears (R == G == B on every opaque pixel), and the transparent
    // pixels keep their colour and alpha.
    auto edge = makeImage(12, 8, {"R", "G", "B", "A"}, [](int x, int y, int c) {
        if (y < 3) return c == 0 ? 1.0f : 0.0f;  // transparent band on top
        if (c == 3) return 1.0f;
        return x < 6 ? 0.0f : 1.0f;
    });
    const BufferPtr out = runFxaa(edge);
    bool blended = false;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 12; ++x) {
            if (y < 3) {
                EXPECT_EQ(at(*out, "R", x, y), 1.0f);
                EXPECT_EQ(at(*out, "A", x, y), 0.0f);
                continue;
            }
            EXPECT_EQ(at(*out, "A", x, y), 1.0f);
            EXPECT_EQ(at(*out, "R", x, y), at(*out, "G", x, y)) << x << "," << y;
            EXPECT_EQ(at(*out, "B", x, y), at(*out, "G", x, y)) << x << "," << y;
            blended |= at(*out, "G", x, y) != at(*edge, "G", x, y);
        }
    EXPECT_TRUE(blended);
}

TEST(FxaaRobustness, AllBackgroundAndTinyImagesAreUnchanged) {
    auto background = makeImage(6, 5, {"R", "G", "B", "A", "Z"}, [](int x, int, int c) {
        return c == 4 ? kInf : (c == 3 ? 0.0f : float(x % 2));
    });
    EXPECT_TRUE(identical(*runFxaa(background), *background));
    for (auto [w, h] : {std::pair{1, 1}, {1, 7}, {7, 1}, {2, 2}}) {
        auto img = greyImage(w, h, [](int x, int y) { return float((x + y) % 2); }, true);
        const BufferPtr out = runFxaa(img);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const float v = at(*out, "G", x, y);
                EXPECT_TRUE(v >= 0.0f && v <= 1.0f) << w << "x" << h;
            }
        if (w * h == 1) {
            EXPECT_TRUE(identical(*out, *img));
        }
    }
}

TEST(FxaaRobustness, InfiniteAndHugeColoursStayFiniteAroundThem) {
    // +inf and -inf pixels are not blendable: they keep their value, no
    // neighbour picks them up. A huge finite HDR value blends (its luma is
    // clamped to 1) and stays finite.
    auto img = greyImage(12, 10, [](int x, int y) {
        if (x == 3 && y == 3) return kInf;
        if (x == 8 && y == 6) return -kInf;
        if (x == 5 && y == 8) return 1e30f;
        return busy(x, y);
    });
    const BufferPtr out = runFxaa(img);
    for (int y = 0; y < 10; ++y)
        for (int x = 0; x < 12; ++x) {
            const float v = at(*out, "R", x, y);
            if ((x == 3 && y == 3) || (x == 8 && y == 6))
                EXPECT_EQ(v, at(*img, "R", x, y));
            else
                EXPECT_TRUE(std::isfinite(v) && v >= 0.0f && v <= 1e30f) << x << "," << y << " " << v;
        }
}

TEST(FxaaRobustness, EveryPresetRunsAndStaysWithinTheInputRange) {
    auto img = greyImage(40, 30, busy, true);
    for (const auto& preset : allPresets()) {
        const BufferPtr out = runFxaa(img, {{"preset", {Value(preset)}}});
        for (std::size_t i = 0; i < out->pixelCount(); ++i) {
            const float v = out->hostFloat("G")[i];
            ASSERT_TRUE(v >= 0.05f && v <= 0.95f) << "preset " << preset << ": " << v;
        }
        EXPECT_FALSE(identical(*out, *img)) << "preset " << preset << " changed nothing";
    }
}

TEST(FxaaRobustness, ResultDoesNotDependOnTheThreadCount) {
    auto img = greyImage(257, 131, busy, true);
    for (const char* preset : {"12", "39"}) {
        const BufferPtr one = runFxaa(img, {{"preset", {Value(preset)}}}, 1);
        const BufferPtr four = runFxaa(img, {{"preset", {Value(preset)}}}, 4);
        EXPECT_TRUE(identical(*one, *four)) << "preset " << preset;
    }
}

// The luma and the contrast check run vectors of pixels with the best SIMD
// instructions of the CPU: every instruction set gives the same bits, with
// NaN, infinite, HDR and transparent pixels among the edges.
TEST(FxaaRobustness, ResultDoesNotDependOnTheSimdInstructionSet) {
    auto img = greyImage(83, 41, busy, true);
    float* r = img->writeFloat("R");
    float* a = img->writeFloat("A");
    for (std::size_t i = 0; i < img->pixelCount(); i += 29) r[i] = i % 2 ? std::numeric_limits<float>::quiet_NaN() : 7.5f;
    for (std::size_t i = 5; i < img->pixelCount(); i += 31) a[i] = i % 2 ? 0.0f : 0.5f;
    r[100] = std::numeric_limits<float>::infinity();
    const BufferPtr in = img;
    for (const char* preset : {"10", "12", "39"}) {
        const auto results = resultsPerSimdTarget([&] { return runFxaa(in, {{"preset", {Value(preset)}}}); });
        for (const auto& [target, out] : results)
            EXPECT_TRUE(identical(*out, *results.front().second)) << preset << ": " << target << " differs from "
                                                                  << results.front().first;
    }
}

TEST(FxaaRobustness, OtherChannelsPassThroughBitForBit) {
    auto img = makeCpuBuffer(9, 8, {{"Z"}, {"R"}, {"G"}, {"B"}, {"value"}, {"objectId", ChannelType::UInt32}});
    for (std::size_t i = 0; i < img->pixelCount(); ++i) {
        const int x = int(i % 9), y = int(i / 9);
        img->writeFloat("Z")[i] = x == 0 ? kInf : 1.0f + 0.1f * float(y);
        img->writeFloat("value")[i] = x == 4 ? kNaN : float(i);
        img->writeUInt("objectId")[i] = std::uint32_t(i * 7u);
        for (const char* c : {"R", "G", "B"}) img->writeFloat(c)[i] = busy(x, y);
    }
    const BufferPtr out = runFxaa(img);
    EXPECT_EQ(out->channels(), img->channels());
    EXPECT_EQ(std::memcmp(out->hostFloat("Z"), img->hostFloat("Z"), 4 * img->pixelCount()), 0);
    EXPECT_EQ(std::memcmp(out->hostFloat("value"), img->hostFloat("value"), 4 * img->pixelCount()), 0);
    EXPECT_EQ(std::memcmp(out->hostUInt("objectId"), img->hostUInt("objectId"), 4 * img->pixelCount()), 0);
}

TEST(FxaaRobustness, AlphaIsBlendedWithTheColourWeight) {
    // Half-transparent black beside opaque white, aligned step: the black
    // column takes t = 0.75 (7/27)^2 of its neighbour, mixed premultiplied.
    auto img = makeImage(10, 5, {"R", "G", "B", "A"}, [](int x, int, int c) {
        if (c == 3) return x < 5 ? 0.5f : 1.0f;
        return x < 5 ? 0.0f : 1.0f;
    });
    const BufferPtr out = runFxaa(img);
    const double t = 0.75 * (7.0 / 27.0) * (7.0 / 27.0);
    const double alpha = 0.5 * (1.0 - t) + t;
    EXPECT_NEAR(at(*out, "A", 4, 2), alpha, 2e-6);
    EXPECT_NEAR(at(*out, "R", 4, 2), t / alpha, 2e-6);
    const double alphaWhite = 1.0 * (1.0 - t) + 0.5 * t;
    EXPECT_NEAR(at(*out, "A", 5, 2), alphaWhite, 2e-6);
    EXPECT_NEAR(at(*out, "R", 5, 2), (1.0 - t) / alphaWhite, 2e-6);
    EXPECT_EQ(at(*out, "A", 2, 2), 0.5f);
}

TEST(FxaaRobustness, BadInputIsAnErrorSayingWhatWasExpected) {
    auto noColour = makeImage(4, 4, {"Z", "value"}, [](int, int, int) { return 1.0f; });
    try {
        runFxaa(noColour);
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("R"));
    }
    auto img = greyImage(4, 4, busy);
    EXPECT_THROW(runFxaa(img, {{"preset", {Value("17")}}}), Error);
    EXPECT_THROW(runFxaa(img, {{"subpix", {Value(1.5)}}}), Error);
}
