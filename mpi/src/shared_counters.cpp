#include <darkroom/error.h>
#include <darkroom/mpi/shared_counters.h>

namespace darkroom::mpi {

SharedCounters::SharedCounters(const Communicator& comm, int count) : count_(count) {
    const MPI_Aint bytes = comm.rank() == 0 ? MPI_Aint(sizeof(std::int64_t)) * count : 0;
    check(MPI_Win_allocate(bytes, sizeof(std::int64_t), MPI_INFO_NULL, comm.handle(), &base_, &window_),
          "MPI_Win_allocate");
    if (comm.rank() == 0)
        for (int i = 0; i < count; ++i) base_[i] = 0;
    // The zeros must be in place before anyone adds.
    comm.barrier();
    check(MPI_Win_lock_all(MPI_MODE_NOCHECK, window_), "MPI_Win_lock_all");
}

SharedCounters::~SharedCounters() {
    MPI_Win_unlock_all(window_);
    MPI_Win_free(&window_);
}

std::int64_t SharedCounters::fetchAdd(int index, std::int64_t delta) {
    if (index < 0 || index >= count_) throw Error("shared counter " + std::to_string(index) + " does not exist");
    std::int64_t before = 0;
    check(MPI_Fetch_and_op(&delta, &before, MPI_INT64_T, 0, index, MPI_SUM, window_), "MPI_Fetch_and_op");
    check(MPI_Win_flush(0, window_), "MPI_Win_flush");
    return before;
}

std::int64_t SharedCounters::read(int index) {
    if (index < 0 || index >= count_) throw Error("shared counter " + std::to_string(index) + " does not exist");
    std::int64_t value = 0, none = 0;
    check(MPI_Fetch_and_op(&none, &value, MPI_INT64_T, 0, index, MPI_NO_OP, window_), "MPI_Fetch_and_op");
    check(MPI_Win_flush(0, window_), "MPI_Win_flush");
    return value;
}

}  // namespace darkroom::mpi
