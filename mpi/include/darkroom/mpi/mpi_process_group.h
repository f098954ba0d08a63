#pragma once
// The framework's ProcessGroup (scene_partition.h) over an MPI communicator.
#include <darkroom/scene/scene_partition.h>
#include <darkroom/mpi/communicator.h>

namespace darkroom::mpi {

class MpiProcessGroup final : public ProcessGroup {
public:
    explicit MpiProcessGroup(const Communicator& comm) : comm_(comm) {}
    int rank() const override { return comm_.rank(); }
    int size() const override { return comm_.size(); }
    std::vector<std::string> allGather(const std::string& mine) override { return comm_.allGather(mine); }

private:
    Communicator comm_;
};

}  // namespace darkroom::mpi
