#include <darkroom/mpi/mpi_process_group.h>

#include <darkroom/mpi/distributed_capture.h>
#include <darkroom/mpi/shared_counters.h>

namespace darkroom::mpi {

namespace {

enum Counter : int { kNext = 0, kFinished = 1, kFailed = 2, kCounters = 3 };

class SharedQueue final : public WorkQueue {
public:
    SharedQueue(const Communicator& comm, std::size_t count) : count_(count), counters_(comm, kCounters) {}
    std::optional<std::size_t> next() override {
        if (counters_.read(kFailed) > 0) return std::nullopt;
        const std::int64_t i = counters_.fetchAdd(kNext);
        if (i < 0 || std::size_t(i) >= count_) return std::nullopt;
        return std::size_t(i);
    }
    void finished() override { counters_.fetchAdd(kFinished); }
    void failed() override { counters_.fetchAdd(kFailed); }
    std::size_t finishedEverywhere() override { return std::size_t(counters_.read(kFinished)); }

private:
    std::size_t count_;
    SharedCounters counters_;  // made and freed collectively, with the queue
};

}  // namespace

MpiProcessGroup::MpiProcessGroup(const Communicator& comm) : comm_(comm), onThisNode_(comm_.ranksOnThisNode()) {}

MpiProcessGroup::MpiProcessGroup(MPI_Comm own, Owned) : comm_(own), owned_(own), onThisNode_(comm_.ranksOnThisNode()) {}

MpiProcessGroup::~MpiProcessGroup() {
    int finalised = 0;
    MPI_Finalized(&finalised);
    if (owned_ != MPI_COMM_NULL && !finalised) MPI_Comm_free(&owned_);
}

std::string MpiProcessGroup::agreedError(const std::string& mine) { return mpi::agreedError(comm_, mine); }

std::vector<std::uint64_t> MpiProcessGroup::exclusiveSums(const std::vector<std::uint64_t>& counts) {
    return mpi::exclusiveSums(comm_, counts);
}

BufferPtr MpiProcessGroup::compositeByDepth(const Buffer& local, const std::vector<std::uint64_t>& primitiveOffsets,
                                            bool keepObjectId, bool keepPrimitiveId) {
    return compositeCapture(comm_, local, primitiveOffsets, keepObjectId, keepPrimitiveId);
}

std::unique_ptr<WorkQueue> MpiProcessGroup::workQueue(std::size_t count) {
    if (size() == 1) return ProcessGroup::workQueue(count);
    return std::make_unique<SharedQueue>(comm_, count);
}

}  // namespace darkroom::mpi
