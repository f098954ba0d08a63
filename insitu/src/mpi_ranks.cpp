// A session over the simulation's MPI communicator.
#include "ranks.h"

#include <darkroom/error.h>
#include <darkroom/mpi/distributed_capture.h>

namespace darkroom::insitu {

namespace {

// Works on its own duplicate of the simulation's communicator, as libraries
// do (IceT, ADIOS2), so its messages never meet the simulation's and its
// error handler stays the simulation's business.
class OverMpi final : public Ranks {
public:
    explicit OverMpi(MPI_Comm own) : own_(own), comm_(own), onThisNode_(comm_.ranksOnThisNode()) {}
    ~OverMpi() override {
        int finalised = 0;
        MPI_Finalized(&finalised);
        if (!finalised) MPI_Comm_free(&own_);
    }
    int rank() const override { return comm_.rank(); }
    int size() const override { return comm_.size(); }
    int onThisNode() const override { return onThisNode_; }
    std::vector<std::string> allGather(const std::string& mine) override { return comm_.allGather(mine); }
    void broadcast(std::string& text) override { comm_.broadcast(text); }
    std::string agreedError(const std::string& mine) override { return mpi::agreedError(comm_, mine); }
    std::vector<std::uint64_t> exclusiveSums(const std::vector<std::uint64_t>& counts) override {
        return mpi::exclusiveSums(comm_, counts);
    }
    BufferPtr composite(const Buffer& local, const std::vector<std::uint64_t>& offsets, bool keepObjectId,
                        bool keepPrimitiveId) override {
        return mpi::compositeCapture(comm_, local, offsets, keepObjectId, keepPrimitiveId);
    }

private:
    MPI_Comm own_;
    mpi::Communicator comm_;
    int onThisNode_;
};

// An MPI error on a handle that is no communicator is raised on
// MPI_COMM_WORLD (MPI_COMM_SELF from MPI 4 on), whose handler is the
// simulation's and by default aborts the job: while a handle is tried, such
// errors are returned instead, then the simulation's handlers are put back.
class ErrorsReturned {
public:
    ErrorsReturned() {
        for (int i = 0; i < 2; ++i) {
            MPI_Comm_get_errhandler(comms_[i], &saved_[i]);
            MPI_Comm_set_errhandler(comms_[i], MPI_ERRORS_RETURN);
        }
    }
    ~ErrorsReturned() {
        for (int i = 0; i < 2; ++i) {
            MPI_Comm_set_errhandler(comms_[i], saved_[i]);
            MPI_Errhandler_free(&saved_[i]);
        }
    }
    ErrorsReturned(const ErrorsReturned&) = delete;
    ErrorsReturned& operator=(const ErrorsReturned&) = delete;

private:
    MPI_Comm comms_[2] = {MPI_COMM_WORLD, MPI_COMM_SELF};
    MPI_Errhandler saved_[2] = {MPI_ERRHANDLER_NULL, MPI_ERRHANDLER_NULL};
};

}  // namespace

std::unique_ptr<Ranks> mpiRanks(int fortranComm) {
    int initialised = 0;
    MPI_Initialized(&initialised);
    if (!initialised) throw Error("in situ: darkroom_insitu_set_mpi_comm needs MPI to be initialised (MPI_Init) first");
    const MPI_Comm comm = MPI_Comm_f2c(MPI_Fint(fortranComm));
    if (comm == MPI_COMM_NULL) throw Error("in situ: the communicator handle " + std::to_string(fortranComm) + " is MPI_COMM_NULL");
    MPI_Comm own = MPI_COMM_NULL;
    int code = MPI_SUCCESS;
    {
        const ErrorsReturned returned;
        code = MPI_Comm_dup(comm, &own);
    }
    const std::string what = "MPI_Comm_dup of the communicator handle " + std::to_string(fortranComm) +
                             " (give MPI_Comm_c2f(comm) in C, the INTEGER handle in Fortran)";
    mpi::check(code, what.c_str());
    // Errors come back as codes, turned into messages, instead of aborting.
    MPI_Comm_set_errhandler(own, MPI_ERRORS_RETURN);
    return std::make_unique<OverMpi>(own);
}

}  // namespace darkroom::insitu
