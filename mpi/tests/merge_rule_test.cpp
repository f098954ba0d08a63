// The merge rule of depth compositing on one process: the nearer hit wins
// with all of its channels; at equal depth the lower rank's hit stays.
#include <darkroom/mpi/depth_compositing.h>

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>

namespace darkroom::mpi {
namespace {

GBufferImage image(int w, int h) {
    GBufferImage g;
    g.width = w;
    g.height = h;
    g.channels = {{"Z", ChannelType::Float32}, {"value", ChannelType::Float32}, {"objectId", ChannelType::UInt32}};
    g.planes.assign(3, std::vector<std::uint32_t>(std::size_t(w) * std::size_t(h)));
    return g;
}

void setPixel(GBufferImage& g, std::size_t i, float z, float value, std::uint32_t id) {
    g.planes[0][i] = std::bit_cast<std::uint32_t>(z);
    g.planes[1][i] = std::bit_cast<std::uint32_t>(value);
    g.planes[2][i] = id;
}

TEST(MergeRule, NearerHitReplacesEveryChannel) {
    GBufferImage mine = image(4, 1);
    const float inf = std::numeric_limits<float>::infinity();
    setPixel(mine, 0, 2.0f, 10.0f, 1);  // other nearer -> replaced
    setPixel(mine, 1, 1.0f, 11.0f, 1);  // other farther -> kept
    setPixel(mine, 2, inf, std::nanf(""), ~0u);  // background, other hits -> replaced
    setPixel(mine, 3, 3.0f, 13.0f, 1);  // equal depth
    // The other image's pixels [0, 4), planar.
    std::vector<std::uint32_t> other(12);
    const float oz[4] = {1.5f, 1.5f, 7.0f, 3.0f}, ov[4] = {20, 21, 22, 23};
    for (int i = 0; i < 4; ++i) {
        other[std::size_t(i)] = std::bit_cast<std::uint32_t>(oz[i]);
        other[std::size_t(4 + i)] = std::bit_cast<std::uint32_t>(ov[i]);
        other[std::size_t(8 + i)] = 2;
    }
    GBufferImage higher = mine;
    EXPECT_EQ(mergeNearest(higher, 0, 4, other.data(), /*otherIsLower=*/false), 2u);
    EXPECT_EQ(std::bit_cast<float>(higher.planes[0][0]), 1.5f);
    EXPECT_EQ(std::bit_cast<float>(higher.planes[1][0]), 20.0f);
    EXPECT_EQ(higher.planes[2][0], 2u);
    EXPECT_EQ(std::bit_cast<float>(higher.planes[1][1]), 11.0f);
    EXPECT_EQ(higher.planes[2][1], 1u);
    EXPECT_EQ(std::bit_cast<float>(higher.planes[0][2]), 7.0f);
    EXPECT_EQ(higher.planes[2][2], 2u);
    // A tie keeps mine when the other image comes from a higher rank...
    EXPECT_EQ(std::bit_cast<float>(higher.planes[1][3]), 13.0f);
    EXPECT_EQ(higher.planes[2][3], 1u);
    // ... and takes the other when it comes from a lower rank.
    GBufferImage lower = mine;
    EXPECT_EQ(mergeNearest(lower, 0, 4, other.data(), /*otherIsLower=*/true), 3u);
    EXPECT_EQ(std::bit_cast<float>(lower.planes[1][3]), 23.0f);
    EXPECT_EQ(lower.planes[2][3], 2u);
}

TEST(MergeRule, WithIdsEqualDepthsGoToTheLowerObjectThenPrimitive) {
    GBufferImage mine;
    mine.width = 3;
    mine.height = 1;
    mine.channels = {{"Z", ChannelType::Float32}, {"objectId", ChannelType::UInt32}, {"primitiveId", ChannelType::UInt32}};
    const std::uint32_t z = std::bit_cast<std::uint32_t>(2.0f);
    mine.planes = {{z, z, z}, {1, 1, 1}, {5, 5, 5}};
    // Planar: Z, objectId, primitiveId of three pixels.
    const std::vector<std::uint32_t> other = {z, z, z, /*objects*/ 0, 1, 2, /*primitives*/ 9, 4, 0};
    // A lower object wins; the same object with a lower primitive wins; a
    // higher object loses even though the other image is from a lower rank.
    EXPECT_EQ(mergeNearest(mine, 0, 3, other.data(), /*otherIsLower=*/true), 2u);
    EXPECT_EQ(mine.planes[1], (std::vector<std::uint32_t>{0, 1, 1}));
    EXPECT_EQ(mine.planes[2], (std::vector<std::uint32_t>{9, 4, 5}));
}

TEST(MergeRule, MergesOnlyTheGivenRange) {
    GBufferImage mine = image(5, 2);
    for (std::size_t i = 0; i < 10; ++i) setPixel(mine, i, 5.0f, 1.0f, 1);
    std::vector<std::uint32_t> other(3 * 3);
    for (int i = 0; i < 3; ++i) {
        other[std::size_t(i)] = std::bit_cast<std::uint32_t>(1.0f);
        other[std::size_t(3 + i)] = std::bit_cast<std::uint32_t>(9.0f);
        other[std::size_t(6 + i)] = 7;
    }
    EXPECT_EQ(mergeNearest(mine, 4, 3, other.data(), false), 3u);
    for (std::size_t i = 0; i < 10; ++i) {
        const bool inRange = i >= 4 && i < 7;
        EXPECT_EQ(std::bit_cast<float>(mine.planes[0][i]), inRange ? 1.0f : 5.0f) << i;
        EXPECT_EQ(mine.planes[2][i], inRange ? 7u : 1u) << i;
    }
}

TEST(GBufferImage, RoundTripsThroughABufferBitForBit) {
    auto b = makeCpuBuffer(3, 2, {{"Z", ChannelType::Float32}, {"objectId", ChannelType::UInt32}});
    float* z = b->writeFloat("Z");
    std::uint32_t* id = b->writeUInt("objectId");
    for (int i = 0; i < 6; ++i) {
        z[i] = i == 2 ? std::numeric_limits<float>::infinity() : float(i) * 0.25f;
        id[i] = i == 2 ? ~0u : std::uint32_t(i);
    }
    b->metadata().attributes["units.Z"] = "world";
    const GBufferImage g = GBufferImage::from(*b);
    EXPECT_EQ(g.channelIndex("objectId"), 1);
    EXPECT_EQ(g.channelIndex("missing"), -1);
    const auto back = g.toBuffer();
    EXPECT_TRUE(identical(*b, *back));
}

}  // namespace
}  // namespace darkroom::mpi
