#include <darkroom/error.h>
#include <darkroom/mpi/communicator.h>
#include <darkroom/mpi/runtime.h>

#include <cstdlib>

namespace darkroom::mpi {

bool launchedByMpiLauncher() {
    for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
        if (std::getenv(v)) return true;
    return false;
}

Runtime::Runtime(int* argc, char*** argv) {
    int initialised = 0;
    MPI_Initialized(&initialised);
    if (initialised || !launchedByMpiLauncher()) return;
    int provided = 0;
    check(MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
    initialisedHere_ = true;
    // Errors come back as codes (turned into darkroom::Error by check())
    // instead of ending the process without a word.
    MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
}

Runtime::~Runtime() {
    if (!initialisedHere_) return;
    int finalised = 0;
    MPI_Finalized(&finalised);
    if (!finalised) MPI_Finalize();
}

bool Runtime::active() const {
    int initialised = 0, finalised = 0;
    MPI_Initialized(&initialised);
    MPI_Finalized(&finalised);
    return initialised && !finalised;
}

}  // namespace darkroom::mpi
