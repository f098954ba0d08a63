#pragma once
// The framework's ProcessGroup (darkroom/core/process_group.h) over an MPI
// communicator: gathering and broadcasting text, agreed errors, exclusive
// sums (MPI_Exscan), compositing G-buffers by depth (binary swap,
// distributed_capture.h) and a work queue on shared counters.
#include <darkroom/core/process_group.h>
#include <darkroom/mpi/communicator.h>

namespace darkroom::mpi {

class MpiProcessGroup final : public ProcessGroup {
public:
    // Over `comm`, which the caller keeps alive and frees.
    explicit MpiProcessGroup(const Communicator& comm);
    // Over `own`, which the group frees at its end (MPI_Comm_free, unless MPI
    // is finalised by then): the in situ API's duplicate of a simulation's
    // communicator.
    struct Owned {};
    MpiProcessGroup(MPI_Comm own, Owned);
    ~MpiProcessGroup() override;
    MpiProcessGroup(const MpiProcessGroup&) = delete;
    MpiProcessGroup& operator=(const MpiProcessGroup&) = delete;

    const Communicator& communicator() const { return comm_; }
    int rank() const override { return comm_.rank(); }
    int size() const override { return comm_.size(); }
    int onThisNode() const override { return onThisNode_; }
    std::vector<std::string> allGather(const std::string& mine) override { return comm_.allGather(mine); }
    void broadcast(std::string& text) override { comm_.broadcast(text); }
    std::string agreedError(const std::string& mine) override;
    std::vector<std::uint64_t> exclusiveSums(const std::vector<std::uint64_t>& counts) override;
    BufferPtr compositeByDepth(const Buffer& local, const std::vector<std::uint64_t>& primitiveOffsets,
                               bool keepObjectId, bool keepPrimitiveId) override;
    // Dynamic self-scheduling on shared counters held by rank 0 (MPI RMA).
    std::unique_ptr<WorkQueue> workQueue(std::size_t count) override;

private:
    Communicator comm_;
    MPI_Comm owned_ = MPI_COMM_NULL;
    int onThisNode_ = 1;
};

}  // namespace darkroom::mpi
