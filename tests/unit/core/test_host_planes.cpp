// Host planes of a huge page (2 MiB) or more are mapped on their own and
// aligned to one (sdk/src/buffer.cpp, framework/core/src/plane_pool.cpp):
// still zeroed where asked, writable to their last pixel, and released.
#include <darkroom/buffer.h>
#include <gtest/gtest.h>

#include <cstdint>

using namespace darkroom;

namespace {

bool allZero(const float* p, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i)
        if (p[i] != 0.0f) return false;
    return true;
}

}  // namespace

TEST(HostPlanes, LargePlanesAreZeroedAlignedToAHugePageAndWritable) {
    for (int round = 0; round < 3; ++round) {  // mapped and unmapped again each time
        auto b = makeCpuBuffer(1024, 1024 + round, {{"Z", ChannelType::Float32}, {"N", ChannelType::Float32}});
        for (const char* c : {"Z", "N"}) {
            float* p = b->writeFloat(c);
            EXPECT_EQ(reinterpret_cast<std::uintptr_t>(p) % (std::uintptr_t(2) << 20), 0u) << c;
            ASSERT_TRUE(allZero(p, b->pixelCount())) << c;
            p[0] = 1.0f;
            p[b->pixelCount() - 1] = 2.0f;  // the last pixel of a size that is not a whole number of huge pages
        }
        EXPECT_EQ(b->hostFloat("Z")[b->pixelCount() - 1], 2.0f);
        EXPECT_NE(b->hostFloat("Z"), b->hostFloat("N"));
    }
}

TEST(HostPlanes, SmallPlanesAreZeroedToo) {
    auto b = makeCpuBuffer(37, 11, {{"Z", ChannelType::Float32}});
    EXPECT_TRUE(allZero(b->hostFloat("Z"), b->pixelCount()));
}
