// Resize: exact block means, depth and ids never blended, identities.
#include "../../normals/tests/simd_targets.h"
#include "run_node.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

using namespace darkroom;
using namespace darkroom::test;
using ::testing::HasSubstr;

namespace {

BufferPtr resize(const BufferPtr& in, Inputs params, int threads = 2) {
    params["image"] = {Value(in)};
    return runImage("Resize", params, threads);
}

std::shared_ptr<WritableBuffer> withCamera(std::shared_ptr<WritableBuffer> b) {
    Camera c;
    c.width = b->width();
    c.height = b->height();
    b->metadata().camera = c;
    return b;
}

}  // namespace

TEST(Resize, BoxHalvingEqualsTheBlockMeansExactly) {
    // Quarter steps: every sum is exact in float, so the means are exact.
    const auto in = withCamera(makeImage(4, 4, {"R", "value"}, [](int x, int y, int c) {
        return float(x * x + 3 * y) * 0.25f + float(c) - (x == 3 && y == 0 ? 7.0f : 0.0f);
    }));
    const BufferPtr out = resize(in, {{"scale", {Value(0.5)}}});
    ASSERT_EQ(out->width(), 2);
    ASSERT_EQ(out->height(), 2);
    EXPECT_EQ(out->metadata().camera->width, 2);
    EXPECT_EQ(out->metadata().camera->height, 2);
    for (const char* c : {"R", "value"}) {
        const float* s = in->hostFloat(c);
        for (int by = 0; by < 2; ++by)
            for (int bx = 0; bx < 2; ++bx) {
                const int i = (2 * by) * 4 + 2 * bx;
                const double mean = (double(s[i]) + s[i + 1] + s[i + 4] + s[i + 5]) / 4.0;
                EXPECT_EQ(out->hostFloat(c)[by * 2 + bx], float(mean)) << c << " block " << bx << "," << by;
            }
    }
}

TEST(Resize, BoxWeightsColourByAlphaAndSkipsNoData) {
    // One 2x2 block: opaque red 1.0 next to transparent black, and a NaN scalar.
    const auto in = makeImage(2, 2, {"R", "A", "value"}, [](int x, int y, int c) {
        if (c == 0) return x == 0 ? 1.0f : 0.0f;
        if (c == 1) return x == 0 ? 1.0f : 0.0f;
        return x == 1 && y == 1 ? kNaN : 3.0f;
    });
    const BufferPtr out = resize(in, {{"width", {Value(1)}}});
    ASSERT_EQ(out->height(), 1);
    EXPECT_EQ(out->hostFloat("R")[0], 1.0f);  // not darkened by the transparent half
    EXPECT_EQ(out->hostFloat("A")[0], 0.5f);  // coverage
    EXPECT_EQ(out->hostFloat("value")[0], 3.0f);
}

TEST(Resize, DepthAndIdsComeFromTheNearestSurfaceInTheFootprint) {
    auto in = makeCpuBuffer(4, 2, {{"Z"}, {"objectId", ChannelType::UInt32}});
    const float z[8] = {kInf, 5, 2, 2, kInf, 3, kInf, kNaN};
    for (int i = 0; i < 8; ++i) {
        in->writeFloat("Z")[i] = z[i];
        in->writeUInt("objectId")[i] = std::uint32_t(i);
    }
    const BufferPtr out = resize(in, {{"width", {Value(2)}}, {"height", {Value(1)}}});
    EXPECT_EQ(out->hostFloat("Z")[0], 3.0f);  // never the average of 5, 3 and inf
    EXPECT_EQ(out->hostUInt("objectId")[0], 5u);
    EXPECT_EQ(out->hostFloat("Z")[1], 2.0f);  // tie: first in scan order
    EXPECT_EQ(out->hostUInt("objectId")[1], 2u);
}

TEST(Resize, OnePixelInputFillsAnyOutput) {
    auto in = makeCpuBuffer(1, 1, {{"Z"}, {"R"}, {"id", ChannelType::UInt32}});
    in->writeFloat("Z")[0] = 4;
    in->writeFloat("R")[0] = 0.3f;
    in->writeUInt("id")[0] = 9;
    for (const char* f : {"box", "bilinear", "nearest"}) {
        const BufferPtr out = resize(in, {{"width", {Value(3)}}, {"height", {Value(2)}}, {"filter", {Value(f)}}});
        ASSERT_EQ(out->pixelCount(), 6u);
        for (std::size_t i = 0; i < 6; ++i) {
            EXPECT_EQ(out->hostFloat("Z")[i], 4.0f) << f;
            EXPECT_FLOAT_EQ(out->hostFloat("R")[i], 0.3f) << f;
            EXPECT_EQ(out->hostUInt("id")[i], 9u) << f;
        }
    }
}

TEST(Resize, NearestUpThenDownIsTheIdentity) {
    const auto in = withCamera(makeImage(5, 3, {"Z", "R", "value"}, [](int x, int y, int c) {
        return (x + y) % 4 == 0 ? (c == 0 ? kInf : kNaN) : float(x * 7 + y * 3 + c);
    }));
    const BufferPtr up = resize(in, {{"scale", {Value(3.0)}}, {"filter", {Value("nearest")}}});
    ASSERT_EQ(up->width(), 15);
    const BufferPtr back = resize(up, {{"width", {Value(5)}}, {"filter", {Value("nearest")}}});
    EXPECT_TRUE(identical(*back, *in));
}

TEST(Resize, BilinearUpsamplingOfARampIsLinearInside) {
    const auto in = makeImage(4, 1, {"value"}, [](int x, int, int) { return float(x); });
    const BufferPtr out = resize(in, {{"width", {Value(8)}}, {"height", {Value(1)}}, {"filter", {Value("bilinear")}}});
    const float want[8] = {0.0f, 0.25f, 0.75f, 1.25f, 1.75f, 2.25f, 2.75f, 3.0f};  // clamped at the ends
    for (int x = 0; x < 8; ++x) EXPECT_EQ(out->hostFloat("value")[x], want[x]) << x;
}

TEST(Resize, SizeRulesAndForwarding) {
    const BufferPtr in = withCamera(makeImage(8, 4, {"R"}, [](int x, int, int) { return float(x); }));
    EXPECT_EQ(resize(in, {}).get(), in.get());  // scale 1: nothing to do
    const BufferPtr h = resize(in, {{"height", {Value(2)}}});
    EXPECT_EQ(h->width(), 4);
    const auto r = runNode("Resize", {{"image", {Value(in)}}, {"width", {Value(8)}}, {"height", {Value(8)}}});
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_THAT(r.warnings[0], HasSubstr("aspect"));
    EXPECT_THAT(errorOf("Resize", {{"image", {Value(in)}}, {"scale", {Value(64.0)}}, {"width", {Value(65536)}},
                                   {"height", {Value(0)}}}),
                HasSubstr("exceeds"));
}

TEST(Resize, ResultDoesNotDependOnTheThreadCount) {
    const auto in = makeImage(67, 45, {"Z", "R", "A", "value"}, [](int x, int y, int c) {
        const std::uint32_t h = std::uint32_t(x) * 73856093u ^ std::uint32_t(y) * 19349663u ^ std::uint32_t(c) * 83492791u;
        return c == 0 && h % 5 == 0 ? kInf : float(h % 1000) / 999.0f;
    });
    for (const char* f : {"box", "bilinear"})
        for (double s : {0.37, 2.6}) {
            const Inputs p = {{"scale", {Value(s)}}, {"filter", {Value(f)}}};
            EXPECT_TRUE(identical(*resize(in, p, 1), *resize(in, p, 4))) << f << " " << s;
        }
}

// Rows of output pixels are resampled with the best SIMD instructions of the
// CPU: every instruction set gives the same bits for every filter, down and up,
// with NaN, infinite and transparent samples and uint32 ids.
TEST(Resize, ResultDoesNotDependOnTheSimdInstructionSet) {
    auto in = makeImage(67, 41, {"Z", "R", "G", "B", "A", "value"}, [](int x, int y, int c) {
        const std::uint32_t h = std::uint32_t(x) * 73856093u ^ std::uint32_t(y) * 19349663u ^ std::uint32_t(c) * 83492791u;
        if (h % 17 == 0) return c == 0 ? kInf : kNaN;
        if (h % 31 == 0) return -kInf;
        if (c == 4) return float(h % 5) * 0.25f;
        return float(h % 1000) * 0.01f + (c == 0 ? 3.0f : 0.0f);
    });
    auto ids = makeCpuBuffer(67, 41, {{"objectId", ChannelType::UInt32}});
    for (std::size_t i = 0; i < ids->pixelCount(); ++i) ids->writeUInt("objectId")[i] = std::uint32_t(i % 7);
    in->setPlane({"objectId", ChannelType::UInt32}, ids->plane("objectId"));
    const BufferPtr image = in;
    for (const char* filter : {"box", "bilinear", "nearest"})
        for (const double scale : {0.5, 0.3, 1.7}) {
            const auto results = resultsPerSimdTarget(
                [&] { return resize(image, {{"filter", {Value(filter)}}, {"scale", {Value(scale)}}}); });
            for (const auto& [target, out] : results)
                EXPECT_TRUE(identical(*out, *results.front().second))
                    << filter << " " << scale << ": " << target << " differs from " << results.front().first;
        }
}
