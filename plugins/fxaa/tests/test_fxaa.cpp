// FXAA on images with known answers: flat areas, an aligned step, staircases.
#include "fxaa_helpers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace darkroom;
using namespace darkroom::test;

namespace {

// FXAA's sub-pixel blend for a pixel whose 3x3 low-pass differs from it by a
// third of the local luma range (every pixel beside a straight, pixel-aligned
// step): subpix * (smoothstep(1/3))^2 = subpix * (7/27)^2.
double alignedStepBlend(double subpix) { return subpix * (7.0 / 27.0) * (7.0 / 27.0); }

// A shallow staircase: white below the line y = 8 + x / 8 (image y down),
// black above; `transposed` swaps x and y to make a steep one.
float staircase(int x, int y, bool transposed) {
    if (transposed) std::swap(x, y);
    return (y + 0.5) > 8.0 + (x + 0.5) / 8.0 ? 1.0f : 0.0f;
}

// Exact area of the pixel below the line (64 x 64 point samples per pixel is
// exact for this slope up to 1/4096).
float coverage(int x, int y, bool transposed) {
    if (transposed) std::swap(x, y);
    int inside = 0;
    for (int j = 0; j < 64; ++j)
        for (int i = 0; i < 64; ++i)
            inside += (y + (j + 0.5) / 64.0) > 8.0 + (x + (i + 0.5) / 64.0) / 8.0;
    return float(inside) / 4096.0f;
}

double rmse(const Buffer& a, const std::function<float(int, int)>& ref) {
    double sum = 0.0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const double d = at(a, "G", x, y) - ref(x, y);
            sum += d * d;
        }
    return std::sqrt(sum / double(a.pixelCount()));
}

}  // namespace

TEST(Fxaa, FlatImagesAreUnchangedExactly) {
    for (const char* preset : {"10", "12", "29", "39"}) {
        auto img = makeImage(9, 7, {"R", "G", "B", "A", "Z", "value"}, [](int x, int y, int c) {
            const float colour[] = {0.3f, 0.55f, 0.9f, 1.0f};
            return c < 4 ? colour[c] : float(x * 10 + y);  // Z and value vary: not looked at
        });
        const BufferPtr out = runFxaa(img, {{"preset", {Value(preset)}}});
        EXPECT_TRUE(identical(*out, *img)) << "preset " << preset;
    }
}

TEST(Fxaa, ContrastBelowTheThresholdsIsLeftAlone) {
    // A gentle ramp from 0.2 to 0.33 in linear: ~0.005 encoded luma per pixel,
    // a cross range of ~0.01, below edgeThresholdMin (0.0833) everywhere.
    auto img = greyImage(32, 4, [](int x, int) { return 0.2f + 0.004f * float(x); });
    EXPECT_TRUE(identical(*runFxaa(img), *img));
    // With both thresholds at 0 every difference counts as an edge.
    const BufferPtr all = runFxaa(img, {{"edgeThreshold", {Value(0.0)}}, {"edgeThresholdMin", {Value(0.0)}}});
    EXPECT_FALSE(identical(*all, *img));
}

TEST(Fxaa, AlignedStepGetsOnlyTheSubpixelBlendOnItsTwoColumns) {
    // Black for x < 8, white from 8: the edge search runs the whole height
    // both ways, so the edge term is 1/2 - L/(2L) = 0 and only the sub-pixel
    // term moves the two columns beside the step towards each other.
    for (double subpix : {0.0, 0.25, 0.75, 1.0}) {
        auto img = greyImage(16, 9, [](int x, int) { return x < 8 ? 0.0f : 1.0f; }, true);
        const BufferPtr out = runFxaa(img, {{"subpix", {Value(subpix)}}});
        const double t = alignedStepBlend(subpix);
        for (int y = 0; y < 9; ++y)
            for (int x = 0; x < 16; ++x) {
                const double want = x == 7 ? t : x == 8 ? 1.0 - t : (x < 8 ? 0.0 : 1.0);
                for (const char* c : {"R", "G", "B"})
                    EXPECT_NEAR(at(*out, c, x, y), want, 2e-6) << c << " at " << x << "," << y << " subpix " << subpix;
                EXPECT_EQ(at(*out, "A", x, y), 1.0f);
                if (x != 7 && x != 8) {
                    EXPECT_EQ(at(*out, "R", x, y), at(*img, "R", x, y));  // exactly
                }
            }
    }
}

TEST(Fxaa, HorizontalAlignedStepBehavesLikeTheVerticalOne) {
    auto img = greyImage(9, 16, [](int, int y) { return y < 8 ? 1.0f : 0.0f; });
    const BufferPtr out = runFxaa(img);
    for (int x = 0; x < 9; ++x) {
        EXPECT_NEAR(at(*out, "G", x, 7), 1.0 - alignedStepBlend(0.75), 2e-6);
        EXPECT_NEAR(at(*out, "G", x, 8), alignedStepBlend(0.75), 2e-6);
        EXPECT_EQ(at(*out, "G", x, 6), 1.0f);
        EXPECT_EQ(at(*out, "G", x, 9), 0.0f);
    }
}

class FxaaStaircase : public ::testing::TestWithParam<std::tuple<const char*, bool>> {};

TEST_P(FxaaStaircase, TurnsEachStepIntoAMonotoneRampAndLeavesFarPixelsAlone) {
    const auto [preset, transposed] = GetParam();
    const int longSide = 96, shortSide = 20;  // the edge crosses rows 8 .. 20
    const int w = transposed ? shortSide : longSide, h = transposed ? longSide : shortSide;
    auto img = greyImage(w, h, [&](int x, int y) { return staircase(x, y, transposed); });
    const BufferPtr out = runFxaa(img, {{"preset", {Value(preset)}}});

    // Walk along the edge's long direction: line index = row (column when
    // transposed), position along it = column (row).
    auto value = [&](const Buffer& b, int line, int pos) {
        return transposed ? at(b, "G", line, pos) : at(b, "G", pos, line);
    };
    int rampsSeen = 0;
    for (int line = 0; line < shortSide; ++line) {
        int intermediate = 0;
        bool crossesEdge = value(*img, line, 0) != value(*img, line, longSide - 1);
        for (int pos = 0; pos < longSide; ++pos) {
            const float v = value(*out, line, pos);
            ASSERT_TRUE(v >= 0.0f && v <= 1.0f) << v;
            if (pos > 0) {
                // Input goes from white (1) to black (0) along every line.
                EXPECT_LE(v, value(*out, line, pos - 1) + 1e-6f)
                    << "not monotone in line " << line << " at " << pos << " (preset " << preset << ")";
            }
            intermediate += v > 0.1f && v < 0.9f;
            // Pixels more than 2 pixels from the edge line are untouched.
            const double edge = 8.0 + (pos + 0.5) / 8.0;
            if (std::fabs(line + 0.5 - edge) > 2.0) {
                EXPECT_EQ(v, value(*img, line, pos)) << "line " << line << " pos " << pos;
            }
        }
        if (crossesEdge && line > 8 && line < shortSide - 1) {
            EXPECT_GE(intermediate, 4) << "line " << line << ": the step was not turned into a ramp";
            ++rampsSeen;
        }
    }
    EXPECT_GE(rampsSeen, 8);

    // And the ramp approximates the true pixel coverage of the edge.
    const double before = rmse(*img, [&](int x, int y) { return coverage(x, y, transposed); });
    const double after = rmse(*out, [&](int x, int y) { return coverage(x, y, transposed); });
    std::printf("[ coverage ] preset %s %s: RMSE against exact coverage %.4f -> %.4f\n", preset,
                transposed ? "steep" : "shallow", before, after);
    EXPECT_LT(after, 0.6 * before);
}

INSTANTIATE_TEST_SUITE_P(Presets, FxaaStaircase,
                         ::testing::Combine(::testing::Values("12", "29", "39"), ::testing::Bool()));
