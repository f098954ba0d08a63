// A runner built without MPI always runs as one process.
#include "processes.h"

namespace darkroom::cli {

ProcessScope::ProcessScope(int*, char***) {}
ProcessScope::~ProcessScope() = default;

ProcessGroup& processGroup() {
    static SingleProcess alone;
    return alone;
}

int defaultThreads() { return 0; }

int failAllProcesses(int code) { return code; }

}  // namespace darkroom::cli
