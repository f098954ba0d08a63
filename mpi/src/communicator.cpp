#include <darkroom/error.h>
#include <darkroom/mpi/communicator.h>

#include <cstdint>
#include <cstdlib>
#include <limits>

namespace darkroom::mpi {

void check(int code, const char* what) {
    if (code == MPI_SUCCESS) return;
    char text[MPI_MAX_ERROR_STRING];
    int length = 0;
    MPI_Error_string(code, text, &length);
    throw Error(std::string("MPI: ") + what + ": " + std::string(text, std::size_t(length)));
}

Communicator::Communicator(MPI_Comm comm) : comm_(comm) {
    check(MPI_Comm_rank(comm_, &rank_), "MPI_Comm_rank");
    check(MPI_Comm_size(comm_, &size_), "MPI_Comm_size");
}

std::vector<std::string> Communicator::allGather(const std::string& mine) const {
    if (mine.size() > std::size_t(std::numeric_limits<int>::max()))
        throw Error("MPI: a message of " + std::to_string(mine.size()) + " bytes is too long to gather");
    int length = int(mine.size());
    std::vector<int> lengths(static_cast<std::size_t>(size_)), offsets(static_cast<std::size_t>(size_));
    check(MPI_Allgather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, comm_), "MPI_Allgather");
    long long total = 0;
    for (int r = 0; r < size_; ++r) {
        offsets[std::size_t(r)] = int(total);
        total += lengths[std::size_t(r)];
    }
    if (total > std::numeric_limits<int>::max())
        throw Error("MPI: gathering " + std::to_string(total) + " bytes exceeds what one MPI call can carry");
    std::string all(std::size_t(total), '\0');
    check(MPI_Allgatherv(mine.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR, comm_),
          "MPI_Allgatherv");
    std::vector<std::string> out;
    for (int r = 0; r < size_; ++r)
        out.push_back(all.substr(std::size_t(offsets[std::size_t(r)]), std::size_t(lengths[std::size_t(r)])));
    return out;
}

void Communicator::broadcast(std::string& text, int root) const {
    unsigned long long length = text.size();
    check(MPI_Bcast(&length, 1, MPI_UNSIGNED_LONG_LONG, root, comm_), "MPI_Bcast");
    if (length > std::size_t(std::numeric_limits<int>::max()))
        throw Error("MPI: a message of " + std::to_string(length) + " bytes is too long to broadcast");
    text.resize(std::size_t(length));
    check(MPI_Bcast(text.data(), int(length), MPI_CHAR, root, comm_), "MPI_Bcast");
}

bool Communicator::allAgree(bool ok) const {
    int mine = ok ? 1 : 0, all = 0;
    check(MPI_Allreduce(&mine, &all, 1, MPI_INT, MPI_LAND, comm_), "MPI_Allreduce");
    return all != 0;
}

void Communicator::barrier() const { check(MPI_Barrier(comm_), "MPI_Barrier"); }

int Communicator::ranksOnThisNode() const {
    MPI_Comm node;
    check(MPI_Comm_split_type(comm_, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &node), "MPI_Comm_split_type");
    int n = 1;
    MPI_Comm_size(node, &n);
    MPI_Comm_free(&node);
    return n;
}

void Communicator::abort(int code) const {
    MPI_Abort(comm_, code);
    std::abort();  // MPI_Abort does not return; this keeps [[noreturn]] honest
}

}  // namespace darkroom::mpi
