// The runner under mpirun: MPI start-up, and MPI_COMM_WORLD as the process
// group every command works over.
#include "processes.h"

#include <darkroom/mpi/communicator.h>
#include <darkroom/mpi/mpi_process_group.h>
#include <darkroom/mpi/runtime.h>

#include <memory>
#include <thread>

namespace darkroom::cli {

namespace {

std::unique_ptr<mpi::Runtime>& runtime() {
    static std::unique_ptr<mpi::Runtime> r;
    return r;
}

// Made when MPI starts, on every rank at once (its constructor is collective).
std::unique_ptr<mpi::MpiProcessGroup>& world() {
    static std::unique_ptr<mpi::MpiProcessGroup> w;
    return w;
}

}  // namespace

ProcessScope::ProcessScope(int* argc, char*** argv) {
    runtime() = std::make_unique<mpi::Runtime>(argc, argv);
    if (!runtime()->active()) return;
    world() = std::make_unique<mpi::MpiProcessGroup>(mpi::Communicator(MPI_COMM_WORLD));
}

ProcessScope::~ProcessScope() {
    world().reset();
    runtime().reset();
}

ProcessGroup& processGroup() {
    static SingleProcess alone;
    if (!world() || world()->size() == 1) return alone;
    return *world();
}

int defaultThreads() {
    const ProcessGroup& g = processGroup();
    if (g.size() == 1) return 0;
    const int cores = int(std::thread::hardware_concurrency());
    return cores > g.onThisNode() ? cores / g.onThisNode() : 1;
}

int failAllProcesses(int code) {
    if (processGroup().size() == 1) return code;
    world()->communicator().abort(code);
}

}  // namespace darkroom::cli
