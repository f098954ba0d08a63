#pragma once
// The processes an in situ session spans: this one alone, or the ranks of
// the simulation's MPI communicator (mpi_ranks.cpp, built with MPI).
#include <darkroom/buffer.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace darkroom::insitu {

class Ranks {
public:
    virtual ~Ranks() = default;
    virtual int rank() const = 0;
    virtual int size() const = 0;
    virtual int onThisNode() const = 0;
    // Every rank's string in rank order (collective).
    virtual std::vector<std::string> allGather(const std::string& mine) = 0;
    // Root's text on every rank (collective).
    virtual void broadcast(std::string& text) = 0;
    // The first error of any rank, or "" (collective).
    virtual std::string agreedError(const std::string& mine) = 0;
    // Per entry, the sum of the lower ranks' counts (collective).
    virtual std::vector<std::uint64_t> exclusiveSums(const std::vector<std::uint64_t>& counts) = 0;
    // Composites `local`, which carries objectId and primitiveId with local
    // primitive ids, by depth; the whole image on rank 0, nullptr elsewhere.
    virtual BufferPtr composite(const Buffer& local, const std::vector<std::uint64_t>& primitiveOffsets,
                                bool keepObjectId, bool keepPrimitiveId) = 0;
};

std::unique_ptr<Ranks> aloneRanks();
// Throws darkroom::Error when the library was built without MPI or the
// handle is not a communicator.
std::unique_ptr<Ranks> mpiRanks(int fortranComm);

}  // namespace darkroom::insitu
