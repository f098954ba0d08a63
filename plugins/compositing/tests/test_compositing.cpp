// Compositing on hand-made inputs with known answers.
#include "../../normals/tests/simd_targets.h"
#include "test_support.h"

#include <darkroom/error.h>
#include <darkroom/core/run_filter.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>

using namespace darkroom;
using ::testing::HasSubstr;

namespace {

const float kNaN = std::numeric_limits<float>::quiet_NaN();
const float kInf = std::numeric_limits<float>::infinity();

FilterRunResult composite(const std::vector<BufferPtr>& images, int threads = 2,
                          std::map<std::string, std::vector<Value>> extra = {}) {
    auto f = test::pluginRegistry().createFilter("Compositing");
    std::vector<Value> v;
    for (const auto& b : images) v.emplace_back(b);
    extra["images"] = v;
    FilterRunOptions o;
    o.threads = threads;
    return runFilter(*f, extra, o);
}

BufferPtr compositeImage(const std::vector<BufferPtr>& images, int threads = 2) {
    return composite(images, threads).outputs.at("image").asImage();
}

// A 1-row image with depth `z` and a channel `name` holding `value`.
std::shared_ptr<WritableBuffer> row(const std::vector<float>& z, const std::string& name,
                                    const std::vector<float>& value) {
    return test::makeImage(int(z.size()), 1, {"Z", name},
                           [&](int x, int, int c) { return c == 0 ? z[std::size_t(x)] : value[std::size_t(x)]; });
}

std::string errorOf(const std::vector<BufferPtr>& images) {
    try {
        composite(images);
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

}  // namespace

TEST(Compositing, NearestDepthWinsAndBringsItsChannels) {
    const auto a = row({1, 5, kInf, 3, 2}, "value", {10, 11, 12, 13, 14});
    const auto b = row({2, 4, kInf, 3, kInf}, "value", {20, 21, 22, 23, 24});
    const BufferPtr out = compositeImage({a, b});
    EXPECT_EQ(out->channelNames(), (std::vector<std::string>{"Z", "value"}));
    const float* z = out->hostFloat("Z");
    const float* v = out->hostFloat("value");
    EXPECT_EQ(z[0], 1.0f);
    EXPECT_EQ(v[0], 10.0f);
    EXPECT_EQ(z[1], 4.0f);
    EXPECT_EQ(v[1], 21.0f);
    EXPECT_EQ(z[2], kInf);  // background in both
    EXPECT_TRUE(std::isnan(v[2]));
    EXPECT_EQ(z[3], 3.0f);  // tie: the lower input index
    EXPECT_EQ(v[3], 13.0f);
    EXPECT_EQ(z[4], 2.0f);
    EXPECT_EQ(v[4], 14.0f);
}

TEST(Compositing, TiesGoToTheLowestIndexAmongMany) {
    std::vector<BufferPtr> in;
    for (int k = 0; k < 4; ++k) in.push_back(row({3, float(5 - k), 7}, "value", {float(k), float(k), float(k)}));
    // Input 3 is nearer in the middle pixel; the rest are ties among all four.
    const BufferPtr out = compositeImage(in);
    EXPECT_EQ(out->hostFloat("value")[0], 0.0f);
    EXPECT_EQ(out->hostFloat("value")[1], 3.0f);
    EXPECT_EQ(out->hostFloat("Z")[1], 2.0f);
    EXPECT_EQ(out->hostFloat("value")[2], 0.0f);
}

TEST(Compositing, BackgroundNeverWinsWhateverItsEncoding) {
    // +inf, NaN and -inf depths are all background; a finite depth behind them wins.
    const auto a = row({kInf, kNaN, -kInf, kNaN}, "value", {1, 2, 3, 4});
    const auto b = row({9, 9, 9, kNaN}, "value", {5, 6, 7, 8});
    const BufferPtr out = compositeImage({a, b});
    for (int x = 0; x < 3; ++x) {
        EXPECT_EQ(out->hostFloat("Z")[x], 9.0f) << x;
        EXPECT_EQ(out->hostFloat("value")[x], float(5 + x)) << x;
    }
    // Background everywhere reads as +inf depth, whatever the inputs held.
    EXPECT_EQ(out->hostFloat("Z")[3], kInf);
    EXPECT_TRUE(std::isnan(out->hostFloat("value")[3]));
}

TEST(Compositing, OutputHasTheUnionOfChannelsWithNoDataWhereTheWinnerLacksOne) {
    auto a = makeCpuBuffer(2, 1, {{"Z"}, {"a"}, {"R"}});
    auto b = makeCpuBuffer(2, 1, {{"Z"}, {"b"}, {"id", ChannelType::UInt32}});
    a->writeFloat("Z")[0] = 1;
    a->writeFloat("Z")[1] = 3;
    b->writeFloat("Z")[0] = 2;
    b->writeFloat("Z")[1] = 2;
    a->writeFloat("a")[0] = a->writeFloat("a")[1] = 0.5f;
    a->writeFloat("R")[0] = a->writeFloat("R")[1] = 0.25f;
    b->writeFloat("b")[0] = b->writeFloat("b")[1] = 7;
    b->writeUInt("id")[0] = b->writeUInt("id")[1] = 42;
    const BufferPtr out = compositeImage({a, b});
    EXPECT_EQ(out->channelNames(), (std::vector<std::string>{"Z", "a", "R", "b", "id"}));
    EXPECT_EQ(out->channelType("id"), ChannelType::UInt32);
    // Pixel 0: input a wins; it has no b and no id.
    EXPECT_EQ(out->hostFloat("a")[0], 0.5f);
    EXPECT_EQ(out->hostFloat("R")[0], 0.25f);
    EXPECT_TRUE(std::isnan(out->hostFloat("b")[0]));
    EXPECT_EQ(out->hostUInt("id")[0], 0xFFFFFFFFu);
    // Pixel 1: input b wins; it has no a and no R.
    EXPECT_TRUE(std::isnan(out->hostFloat("a")[1]));
    EXPECT_TRUE(std::isnan(out->hostFloat("R")[1]));
    EXPECT_EQ(out->hostFloat("b")[1], 7.0f);
    EXPECT_EQ(out->hostUInt("id")[1], 42u);
}

TEST(Compositing, AllBackgroundPixelIsTransparentBlackWithNoIdAndNoData) {
    auto a = makeCpuBuffer(1, 1, {{"Z"}, {"R"}, {"G"}, {"B"}, {"A"}, {"value"}, {"objectId", ChannelType::UInt32}});
    a->writeFloat("Z")[0] = kInf;
    a->writeFloat("R")[0] = a->writeFloat("G")[0] = a->writeFloat("B")[0] = a->writeFloat("A")[0] = 0.7f;
    a->writeUInt("objectId")[0] = 3;
    const BufferPtr out = compositeImage({a, a});
    EXPECT_EQ(out->hostFloat("Z")[0], kInf);
    for (const char* c : {"R", "G", "B", "A"}) EXPECT_EQ(out->hostFloat(c)[0], 0.0f) << c;
    EXPECT_TRUE(std::isnan(out->hostFloat("value")[0]));
    EXPECT_EQ(out->hostUInt("objectId")[0], 0xFFFFFFFFu);
}

TEST(Compositing, OneInputIsForwardedUntouched) {
    const BufferPtr a = row({1, kInf}, "value", {3, 4});
    EXPECT_EQ(compositeImage({a}).get(), a.get());
}

TEST(Compositing, SizeMismatchNamesBothSizes) {
    const auto a = test::makeImage(4, 3, {"Z"}, [](int, int, int) { return 1.0f; });
    const auto b = test::makeImage(3, 4, {"Z"}, [](int, int, int) { return 1.0f; });
    const std::string e = errorOf({a, b});
    EXPECT_THAT(e, HasSubstr("4x3"));
    EXPECT_THAT(e, HasSubstr("3x4"));
    EXPECT_THAT(e, HasSubstr("same size"));
}

TEST(Compositing, ChannelTypeConflictAndMissingDepthAreClearErrors) {
    auto a = makeCpuBuffer(1, 1, {{"Z"}, {"id", ChannelType::Float32}});
    auto b = makeCpuBuffer(1, 1, {{"Z"}, {"id", ChannelType::UInt32}});
    const std::string conflict = errorOf({a, b});
    EXPECT_THAT(conflict, HasSubstr("'id'"));
    EXPECT_THAT(conflict, HasSubstr("uint32"));

    const auto noDepth = test::makeImage(1, 1, {"depth", "value"}, [](int, int, int) { return 1.0f; });
    const std::string missing = errorOf({a, noDepth});
    EXPECT_THAT(missing, HasSubstr("'Z'"));
    EXPECT_THAT(missing, HasSubstr("depth, value"));

    EXPECT_THROW(composite({}), Error);
}

TEST(Compositing, DepthChannelCanBeRenamed) {
    const auto a = test::makeImage(2, 1, {"depth", "v"}, [](int x, int, int c) { return c ? 1.0f : float(1 + x); });
    const auto b = test::makeImage(2, 1, {"depth", "v"}, [](int x, int, int c) { return c ? 2.0f : float(2 - x); });
    const BufferPtr out =
        composite({a, b}, 2, {{"depthChannel", {Value("depth")}}}).outputs.at("image").asImage();
    EXPECT_EQ(out->hostFloat("v")[0], 1.0f);
    EXPECT_EQ(out->hostFloat("v")[1], 2.0f);
    EXPECT_EQ(out->hostFloat("depth")[1], 1.0f);
}

TEST(Compositing, KeepsTheFirstCameraAndWarnsWhenTheyDiffer) {
    auto a = row({1}, "v", {1});
    auto b = row({2}, "v", {2});
    Camera ca, cb;
    ca.width = cb.width = 1;
    ca.height = cb.height = 1;
    cb.fovYDegrees = 50;
    a->metadata().camera = ca;
    b->metadata().camera = cb;
    const auto r = composite({b, a});
    EXPECT_EQ(r.outputs.at("image").asImage()->metadata().camera, cb);
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_THAT(r.warnings[0], HasSubstr("camera"));
    // A perspective camera's unused orthographic height does not matter.
    cb = ca;
    cb.viewHeight = 7;
    b->metadata().camera = cb;
    EXPECT_TRUE(composite({a, b}).warnings.empty());
}

TEST(Compositing, ResultDoesNotDependOnTheThreadCount) {
    auto make = [](int seed) {
        return test::makeImage(97, 61, {"Z", "value"}, [seed](int x, int y, int c) {
            const std::uint32_t hsh = std::uint32_t(x) * 73856093u ^ std::uint32_t(y) * 19349663u ^ std::uint32_t(seed) * 83492791u;
            if (c == 1) return float(hsh % 1000);
            return hsh % 7 == 0 ? kInf : float(hsh % 13);  // many ties and some background
        });
    };
    const std::vector<BufferPtr> in = {make(1), make(2), make(3)};
    EXPECT_TRUE(identical(*compositeImage(in, 1), *compositeImage(in, 4)));
}

// The nearest input is chosen for vectors of pixels with the best SIMD
// instructions of the CPU: every instruction set gives the same bits (ties,
// background, NaN and -inf depths among the inputs).
TEST(Compositing, ResultDoesNotDependOnTheSimdInstructionSet) {
    auto make = [](int seed) {
        return test::makeImage(71, 23, {"Z", "value"}, [seed](int x, int y, int c) {
            const std::uint32_t hsh = std::uint32_t(x) * 73856093u ^ std::uint32_t(y) * 19349663u ^ std::uint32_t(seed) * 83492791u;
            if (c == 1) return float(hsh % 1000);
            if (hsh % 11 == 0) return hsh % 2 ? kNaN : -kInf;
            return hsh % 7 == 0 ? kInf : float(hsh % 13);
        });
    };
    const std::vector<BufferPtr> in = {make(1), make(2), make(3)};
    const auto results = test::resultsPerSimdTarget([&] { return compositeImage(in); });
    for (const auto& [target, out] : results)
        EXPECT_TRUE(identical(*out, *results.front().second)) << target << " differs from " << results.front().first;
}
