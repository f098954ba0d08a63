// Dynamic work sharing: every index is taken exactly once over all ranks.
#include <darkroom/mpi/shared_counters.h>

#include <gtest/gtest.h>

#include <chrono>
#include <set>
#include <string>
#include <thread>

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

TEST(SharedCounters, ARankWithCostlierItemsTakesFewer) {
    // Dynamic self-scheduling balances by cost, not by count: rank 1's items
    // take ten times as long (a sleep, so the machine's load does not matter).
    const Communicator comm(MPI_COMM_WORLD);
    if (comm.size() < 3) GTEST_SKIP() << "needs at least 3 ranks";
    constexpr int kItems = 120;
    int mine = 0;
    {
        SharedCounters counters(comm, 1);
        while (counters.fetchAdd(0) < kItems) {
            ++mine;
            std::this_thread::sleep_for(std::chrono::milliseconds(comm.rank() == 1 ? 30 : 3));
        }
        comm.barrier();
    }
    std::vector<int> counts;
    for (const auto& s : comm.allGather(std::to_string(mine))) counts.push_back(std::stoi(s));
    int total = 0, others = kItems;
    for (int r = 0; r < comm.size(); ++r) {
        total += counts[std::size_t(r)];
        if (r != 1) others = std::min(others, counts[std::size_t(r)]);
    }
    EXPECT_EQ(total, kItems);
    EXPECT_LT(counts[1] * 3, others) << "rank 1 took " << counts[1] << " items, the least of the others " << others;
}

}  // namespace
}  // namespace darkroom::mpi
