// Dynamic work sharing: every index is taken exactly once over all ranks.
#include <darkroom/mpi/shared_counters.h>

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace darkroom::mpi {
namespace {

TEST(SharedCounters, EveryIndexIsTakenOnceAndTheSecondCounterCountsThem) {
    const Communicator comm(MPI_COMM_WORLD);
    constexpr int kItems = 200;
    std::string taken;
    {
        SharedCounters counters(comm, 2);
        for (;;) {
            const std::int64_t i = counters.fetchAdd(0);
            if (i >= kItems) break;
            taken += std::to_string(i) + " ";
            counters.fetchAdd(1);
        }
        comm.barrier();
        EXPECT_EQ(counters.read(1), kItems);
        EXPECT_EQ(counters.read(0), kItems + comm.size());  // each rank's last, unused fetch
        comm.barrier();
    }
    std::multiset<int> all;
    for (const auto& s : comm.allGather(taken)) {
        std::size_t pos = 0;
        while (pos < s.size()) {
            const std::size_t end = s.find(' ', pos);
            all.insert(std::stoi(s.substr(pos, end - pos)));
            pos = end + 1;
        }
    }
    ASSERT_EQ(all.size(), std::size_t(kItems));
    for (int i = 0; i < kItems; ++i) EXPECT_EQ(all.count(i), 1u) << i;
}

}  // namespace
}  // namespace darkroom::mpi
