#pragma once
// The processes one invocation of the runner spans: this process alone, or
// the ranks of an `mpirun -np N darkroom ...` (docs/scale-out.md). MPI is
// started only when an MPI launcher started us, so a plain `darkroom` run
// never touches MPI; a build without MPI always runs alone.
namespace darkroom::cli {

struct Processes {
    int rank = 0;
    int size = 1;
    int onThisNode = 1;  // ranks sharing this machine's cores
    bool root() const { return rank == 0; }
};

// Starts MPI when launched by mpirun (and built with MPI) and ends it on
// destruction. Create it first thing in main.
class ProcessScope {
public:
    ProcessScope(int* argc, char*** argv);
    ~ProcessScope();
    ProcessScope(const ProcessScope&) = delete;
    ProcessScope& operator=(const ProcessScope&) = delete;
};

const Processes& processes();

// Worker threads per process when -j is not given: 0 (all cores) alone, the
// node's cores divided among its ranks under mpirun.
int defaultThreads();

// After an error that only this process met: alone, returns `code`; under
// mpirun, ends every rank (MPI_Abort), since the others may be waiting for
// this one in a collective operation.
int failAllProcesses(int code);

}  // namespace darkroom::cli
