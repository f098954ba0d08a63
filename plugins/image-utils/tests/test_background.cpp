// Background: exact gradient ends, straight-alpha "under", coverage from depth.
#include "run_node.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

using namespace darkroom;
using namespace darkroom::test;
using ::testing::HasSubstr;

namespace {
const Color kTop{0.1f, 0.2f, 0.7f, 1.0f};
const Color kBottom{0.9f, 0.6f, 0.3f, 1.0f};

BufferPtr gradientOver(const BufferPtr& img) {
    return runImage("Background", {{"image", {Value(img)}}, {"mode", {Value("gradient")}}, {"top", {Value(kTop)}},
                                   {"bottom", {Value(kBottom)}}});
}
}  // namespace

TEST(Background, GradientIsExactOnTheFirstAndLastRows) {
    // Transparent everywhere, with NaN colour that must not show through.
    const auto img = makeImage(3, 5, {"R", "G", "B", "A"}, [](int, int, int c) { return c == 3 ? 0.0f : kNaN; });
    const BufferPtr out = gradientOver(img);
    for (int x = 0; x < 3; ++x) {
        EXPECT_EQ(out->hostFloat("R")[x], kTop.r);
        EXPECT_EQ(out->hostFloat("G")[x], kTop.g);
        EXPECT_EQ(out->hostFloat("B")[x], kTop.b);
        EXPECT_EQ(out->hostFloat("A")[x], 1.0f);
        const std::size_t last = 4 * 3 + std::size_t(x);
        EXPECT_EQ(out->hostFloat("R")[last], kBottom.r);
        EXPECT_EQ(out->hostFloat("G")[last], kBottom.g);
        EXPECT_EQ(out->hostFloat("B")[last], kBottom.b);
    }
    // The middle row is halfway.
    EXPECT_FLOAT_EQ(out->hostFloat("R")[2 * 3], 0.5f);
    EXPECT_FLOAT_EQ(out->hostFloat("B")[2 * 3], 0.5f);
}

TEST(Background, OpaquePixelsStayAndHalfAlphaIsTheAverage) {
    const auto img = makeImage(3, 1, {"R", "G", "B", "A", "Z"}, [](int x, int, int c) {
        if (c == 4) return 3.0f;
        return c == 3 ? (x == 0 ? 1.0f : 0.5f) : 0.25f;
    });
    const BufferPtr out = runImage("Background", {{"image", {Value(BufferPtr(img))}}, {"mode", {Value("color")}},
                                                  {"color", {Value(Color{0.75f, 0.75f, 0.75f, 1.0f})}}});
    EXPECT_EQ(out->hostFloat("R")[0], 0.25f);
    EXPECT_EQ(out->hostFloat("R")[1], 0.5f);  // 0.25 * 0.5 + 0.75 * 0.5
    EXPECT_EQ(out->hostFloat("A")[1], 1.0f);
    EXPECT_EQ(out->hostFloat("Z")[1], 3.0f);  // passes through
}

TEST(Background, WithoutAlphaDepthTellsSceneFromBackground) {
    const auto img = makeImage(2, 1, {"R", "G", "B", "Z"}, [](int x, int, int c) {
        return c == 3 ? (x == 1 ? kInf : 1.0f) : 0.5f;
    });
    const BufferPtr out = runImage("Background", {{"image", {Value(BufferPtr(img))}}, {"mode", {Value("color")}},
                                                  {"color", {Value(Color{0, 0, 1, 1})}}});
    EXPECT_EQ(out->channelNames(), (std::vector<std::string>{"R", "G", "B", "Z", "A"}));
    EXPECT_EQ(out->hostFloat("R")[0], 0.5f);
    EXPECT_EQ(out->hostFloat("R")[1], 0.0f);
    EXPECT_EQ(out->hostFloat("B")[1], 1.0f);
    EXPECT_EQ(out->hostFloat("Z")[1], kInf);

    const auto bare = makeImage(1, 1, {"R", "G", "B"}, [](int, int, int) { return 0.5f; });
    EXPECT_THAT(errorOf("Background", {{"image", {Value(BufferPtr(bare))}}}), HasSubstr("neither alpha A nor depth Z"));
}
