#pragma once
// A few 64-bit counters that every rank can add to atomically, held by rank
// 0 in an MPI-3 RMA window (MPI_Fetch_and_op under a passive lock_all).
//
// The runner hands out work with it: each rank takes the next entry when it
// has finished its last one, so a rank that draws expensive entries takes
// fewer of them; the balance follows the measured cost of each entry, not
// the count. Rank 0 is not a dedicated master: it works too, and the others
// need nothing from it but the window. Within one node OpenMPI serves the
// window from shared memory; across nodes, whether a fetch waits for rank 0
// to enter MPI depends on the transport (UCX atomics do not).
#include <darkroom/mpi/communicator.h>

#include <cstdint>

namespace darkroom::mpi {

class SharedCounters {
public:
    // Collective. All counters start at 0.
    SharedCounters(const Communicator& comm, int count);
    // Collective.
    ~SharedCounters();
    SharedCounters(const SharedCounters&) = delete;
    SharedCounters& operator=(const SharedCounters&) = delete;

    // Adds `delta` to counter `index` and returns its value before.
    std::int64_t fetchAdd(int index, std::int64_t delta = 1);
    std::int64_t read(int index);

private:
    int count_;
    MPI_Win window_ = MPI_WIN_NULL;
    std::int64_t* base_ = nullptr;
};

}  // namespace darkroom::mpi
