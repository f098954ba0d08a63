// The framework's ProcessGroup over MPI: gathering strings in rank order.
#include <darkroom/mpi/mpi_process_group.h>

#include <gtest/gtest.h>

namespace darkroom::mpi {
namespace {

TEST(MpiProcessGroup, GathersEveryRanksStringInRankOrder) {
    const Communicator comm(MPI_COMM_WORLD);
    MpiProcessGroup group(comm);
    EXPECT_EQ(group.rank(), comm.rank());
    EXPECT_EQ(group.size(), comm.size());
    // Unequal lengths, an empty one, and bytes that are not text.
    std::string mine(std::size_t(comm.rank()), char('a' + comm.rank()));
    mine += '\0';
    const auto all = group.allGather(mine);
    ASSERT_EQ(all.size(), std::size_t(comm.size()));
    for (int r = 0; r < comm.size(); ++r) {
        std::string want(std::size_t(r), char('a' + r));
        want += '\0';
        EXPECT_EQ(all[std::size_t(r)], want);
    }
}

TEST(Communicator, BroadcastAndAgreement) {
    const Communicator comm(MPI_COMM_WORLD);
    std::string text = comm.rank() == 0 ? "from rank zero" : "";
    comm.broadcast(text);
    EXPECT_EQ(text, "from rank zero");
    EXPECT_TRUE(comm.allAgree(true));
    EXPECT_FALSE(comm.allAgree(comm.rank() != comm.size() - 1));
    EXPECT_GE(comm.ranksOnThisNode(), 1);
}

}  // namespace
}  // namespace darkroom::mpi
