// A session over the simulation's MPI communicator.
#include "ranks.h"

#include <darkroom/error.h>
#include <darkroom/mpi/communicator.h>
#include <darkroom/mpi/mpi_process_group.h>

namespace darkroom::insitu {

namespace {

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

std::unique_ptr<ProcessGroup> mpiRanks(int fortranComm) {
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
    // Its own duplicate, as libraries do (IceT, ADIOS2), so its messages
    // never meet the simulation's and its error handler stays the
    // simulation's business.
    return std::make_unique<mpi::MpiProcessGroup>(own, mpi::MpiProcessGroup::Owned{});
}

}  // namespace darkroom::insitu
