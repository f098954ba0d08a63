// The runner under mpirun: MPI start-up and the rank/size every command reads.
#include "processes.h"

#include <darkroom/mpi/communicator.h>
#include <darkroom/mpi/runtime.h>

#include <memory>
#include <thread>

namespace darkroom::cli {

namespace {

Processes& state() {
    static Processes p;
    return p;
}

std::unique_ptr<mpi::Runtime>& runtime() {
    static std::unique_ptr<mpi::Runtime> r;
    return r;
}

}  // namespace

ProcessScope::ProcessScope(int* argc, char*** argv) {
    runtime() = std::make_unique<mpi::Runtime>(argc, argv);
    if (!runtime()->active()) return;
    const mpi::Communicator world(MPI_COMM_WORLD);
    state().rank = world.rank();
    state().size = world.size();
    state().onThisNode = world.ranksOnThisNode();
}

ProcessScope::~ProcessScope() { runtime().reset(); }

const Processes& processes() { return state(); }

int defaultThreads() {
    if (state().size == 1) return 0;
    const int cores = int(std::thread::hardware_concurrency());
    return cores > state().onThisNode ? cores / state().onThisNode : 1;
}

int failAllProcesses(int code) {
    if (state().size == 1) return code;
    mpi::Communicator(MPI_COMM_WORLD).abort(code);
}

}  // namespace darkroom::cli
