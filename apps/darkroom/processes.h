#pragma once
// The processes one invocation of the runner spans: this process alone, or
// the ranks of an `mpirun -np N darkroom ...` (docs/scale-out.md), as the
// ProcessGroup the workflows work over. MPI is started only when an MPI
// launcher started us, so a plain `darkroom` run never touches MPI; a build
// without MPI always runs alone.
#include <darkroom/core/process_group.h>

namespace darkroom::cli {

// Starts MPI when launched by mpirun (and built with MPI) and ends it on
// destruction. Create it first thing in main.
class ProcessScope {
public:
    ProcessScope(int* argc, char*** argv);
    ~ProcessScope();
    ProcessScope(const ProcessScope&) = delete;
    ProcessScope& operator=(const ProcessScope&) = delete;
};

// This process alone, or MPI_COMM_WORLD under mpirun.
ProcessGroup& processGroup();

// Worker threads per process when -j is not given: 0 (all cores) alone, the
// node's cores divided among its ranks under mpirun.
int defaultThreads();

// After an error that only this process met: alone, returns `code`; under
// mpirun, ends every rank (MPI_Abort), since the others may be waiting for
// this one in a collective operation.
int failAllProcesses(int code);

}  // namespace darkroom::cli
