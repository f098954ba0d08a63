#pragma once
// The few MPI operations Darkroom needs, on a communicator it does not own:
// rank and size, gathering and broadcasting byte strings, agreement on
// success, and the processes sharing this node. Failures of MPI itself throw
// darkroom::Error with MPI's own message.
#include <mpi.h>

#include <string>
#include <vector>

namespace darkroom::mpi {

// Throws darkroom::Error "MPI: <what>: <MPI's message>" unless code is MPI_SUCCESS.
void check(int code, const char* what);

class Communicator {
public:
    explicit Communicator(MPI_Comm comm = MPI_COMM_WORLD);

    MPI_Comm handle() const { return comm_; }
    int rank() const { return rank_; }
    int size() const { return size_; }

    // Every rank's string, in rank order, on every rank (collective).
    std::vector<std::string> allGather(const std::string& mine) const;
    // `text` from `root` on every rank (collective).
    void broadcast(std::string& text, int root = 0) const;
    // True on every rank when `ok` is true on every rank (collective).
    bool allAgree(bool ok) const;
    void barrier() const;
    // Processes of this communicator on this node (MPI_Comm_split_type
    // shared), to share the node's cores among them (collective).
    int ranksOnThisNode() const;
    // Ends every process of the communicator with `code` (MPI_Abort): the way
    // out when one rank fails where the others may wait in a collective.
    [[noreturn]] void abort(int code) const;

private:
    MPI_Comm comm_;
    int rank_ = 0;
    int size_ = 1;
};

}  // namespace darkroom::mpi
