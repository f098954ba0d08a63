#pragma once
// MPI start-up for programs that run with or without mpirun (the runner, the
// in situ API): MPI is initialised only when the process was started by an
// MPI launcher, so a plain `darkroom capture` never touches MPI.

namespace darkroom::mpi {

// True when the environment says an MPI launcher started this process
// (OpenMPI's OMPI_COMM_WORLD_SIZE, PMIx's PMIX_RANK, Hydra/Slurm PMI's PMI_RANK).
bool launchedByMpiLauncher();

// Initialises MPI (thread level FUNNELED: only the main thread calls MPI,
// worker threads compute) when launched by mpirun and not yet initialised,
// and finalises it on destruction if it initialised it.
class Runtime {
public:
    Runtime(int* argc, char*** argv);
    ~Runtime();
    Runtime(const Runtime&) = delete;
    Runtime& operator=(const Runtime&) = delete;

    // MPI is initialised (by us or by the program that loaded us).
    bool active() const;

private:
    bool initialisedHere_ = false;
};

}  // namespace darkroom::mpi
