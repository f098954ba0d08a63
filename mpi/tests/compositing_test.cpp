// Depth compositing over the ranks of MPI_COMM_WORLD (run with 3 and 4
// ranks): the composite equals a reference computed on one rank from every
// rank's image, bit for bit, for both algorithms and any root.
#include <darkroom/error.h>
#include <darkroom/mpi/depth_compositing.h>

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>

namespace darkroom::mpi {
namespace {

std::uint32_t hash(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

// Rank r's G-buffer: depths from a few levels (so ranks tie often) or
// background; every other channel says which rank and pixel it came from.
// Object ids run opposite to ranks, so that a tie goes to the higher rank
// when ids are there to break it.
int worldSize() {
    int size = 1;
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    return size;
}

GBufferImage rankImage(int rank, int w, int h, bool ids = true) {
    GBufferImage g;
    g.width = w;
    g.height = h;
    g.channels = {{"Z", ChannelType::Float32},     {"temperature", ChannelType::Float32},
                  {"N.x", ChannelType::Float32},   {"objectId", ChannelType::UInt32},
                  {"primitiveId", ChannelType::UInt32}};
    const std::size_t n = std::size_t(w) * std::size_t(h);
    g.planes.assign(g.channels.size(), std::vector<std::uint32_t>(n));
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint32_t k = hash(std::uint32_t(i) * 131u + std::uint32_t(rank) * 7919u);
        const bool hit = k % 5 != 0;
        const float z = hit ? 1.0f + float(k % 3) : std::numeric_limits<float>::infinity();
        g.planes[0][i] = std::bit_cast<std::uint32_t>(z);
        g.planes[1][i] = std::bit_cast<std::uint32_t>(hit ? float(rank) * 1000.0f + float(i) : std::nanf(""));
        g.planes[2][i] = std::bit_cast<std::uint32_t>(hit ? 0.5f * float(rank) : std::nanf(""));
        g.planes[3][i] = hit ? std::uint32_t(worldSize() - 1 - rank) : ~0u;
        g.planes[4][i] = hit ? std::uint32_t(i) : ~0u;
    }
    if (!ids) {
        g.channels.resize(3);
        g.planes.resize(3);
    }
    g.metadata.attributes["units.Z"] = "world";
    return g;
}

// Per pixel, the image of the rank with the smallest (Z, objectId,
// primitiveId, rank), or (Z, rank) without ids.
GBufferImage reference(int ranks, int w, int h, bool ids) {
    GBufferImage best = rankImage(0, w, h, ids);
    for (int r = 1; r < ranks; ++r) {
        const GBufferImage g = rankImage(r, w, h, ids);
        for (std::size_t i = 0; i < best.pixelCount(); ++i) {
            const float z = std::bit_cast<float>(g.planes[0][i]), bz = std::bit_cast<float>(best.planes[0][i]);
            const bool idsLower = ids && std::isfinite(z) &&
                                  (g.planes[3][i] < best.planes[3][i] ||
                                   (g.planes[3][i] == best.planes[3][i] && g.planes[4][i] < best.planes[4][i]));
            if (z < bz || (z == bz && idsLower))
                for (std::size_t c = 0; c < g.planes.size(); ++c) best.planes[c][i] = g.planes[c][i];
        }
    }
    return best;
}

void expectComposite(CompositeAlgorithm algorithm, int root, int w, int h, bool tiny = false, bool ids = true) {
    const Communicator comm(MPI_COMM_WORLD);
    GBufferImage mine = rankImage(comm.rank(), w, h, ids);
    CompositeOptions o;
    o.algorithm = algorithm;
    o.root = root;
    CompositeStats stats;
    const bool isRoot = compositeByDepth(comm, mine, o, &stats);
    EXPECT_EQ(isRoot, comm.rank() == root);
    if (!isRoot) return;
    const GBufferImage want = reference(comm.size(), w, h, ids);
    std::size_t fromOtherRanks = 0, ties = 0;
    for (std::size_t i = 0; i < want.pixelCount(); ++i) {
        for (std::size_t c = 0; c < want.planes.size(); ++c)
            ASSERT_EQ(mine.planes[c][i], want.planes[c][i])
                << toString(algorithm) << " root " << root << ": pixel " << i << " channel " << want.channels[c].name;
        // The winner's rank, from its "temperature" (rank * 1000 + pixel).
        const float value = std::bit_cast<float>(want.planes[1][i]);
        fromOtherRanks += std::isfinite(value) && int(value / 1000.0f) != root;
    }
    for (std::size_t i = 0; i < want.pixelCount(); ++i) {
        // Count pixels where another rank had the same depth as the winner.
        int level = 0;
        for (int r = 0; r < comm.size(); ++r)
            level += rankImage(r, w, h, ids).planes[0][i] == want.planes[0][i];
        ties += level > 1 && std::isfinite(std::bit_cast<float>(want.planes[0][i]));
    }
    // The test is only meaningful if it exercised both kinds of pixels.
    if (!tiny) {
        EXPECT_GT(fromOtherRanks, 0u);
        EXPECT_GT(ties, 0u);
    }
    EXPECT_EQ(mine.metadata.attributes.at("units.Z"), "world");
}

TEST(DepthCompositing, BinarySwapEqualsTheReferenceAtRankZero) {
    expectComposite(CompositeAlgorithm::BinarySwap, 0, 37, 23);
}

TEST(DepthCompositing, BinarySwapEqualsTheReferenceAtTheLastRank) {
    int size = 1;
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    expectComposite(CompositeAlgorithm::BinarySwap, size - 1, 64, 17);
}

TEST(DepthCompositing, ReduceEqualsTheReference) { expectComposite(CompositeAlgorithm::Reduce, 0, 37, 23); }

TEST(DepthCompositing, WithoutIdsTiesGoToTheLowerRank) {
    expectComposite(CompositeAlgorithm::BinarySwap, 0, 37, 23, false, /*ids=*/false);
    expectComposite(CompositeAlgorithm::Reduce, 0, 37, 23, false, /*ids=*/false);
}

TEST(DepthCompositing, AnImageSmallerThanTheRankCountStillComposites) {
    expectComposite(CompositeAlgorithm::BinarySwap, 0, 1, 2, /*tiny=*/true);
}

TEST(DepthCompositing, DifferentChannelsOnOneRankFailEverywhereWithTheRankNamed) {
    const Communicator comm(MPI_COMM_WORLD);
    GBufferImage mine = rankImage(comm.rank(), 8, 8);
    if (comm.rank() == 1) mine.channels[1].name = "pressure";
    try {
        compositeByDepth(comm, mine);
        ADD_FAILURE() << "expected an error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("rank 1 holds a G-buffer 8x8 [Z:float32, pressure"), std::string::npos)
            << e.what();
    }
}

TEST(DepthCompositing, WithoutZEveryRankFails) {
    const Communicator comm(MPI_COMM_WORLD);
    GBufferImage mine = rankImage(comm.rank(), 4, 4);
    mine.channels[0].name = "depth";
    EXPECT_THROW(compositeByDepth(comm, mine), Error);
}

}  // namespace
}  // namespace darkroom::mpi
