#pragma once
// Runs a program (the runner alone, or mpirun with the runner) and captures
// its exit code and output, for the tests that compare a run over MPI ranks
// with a run in one process.
#include <string>
#include <vector>

namespace darkroom::test {

struct RunResult {
    int exitCode = -1;
    std::string out, err;
};

// `argv[0]` is the program's path. Adds `env` (NAME=VALUE) to a copy of the
// environment without DARKROOM_PLUGIN_PATH.
RunResult runProgram(const std::vector<std::string>& argv, const std::vector<std::string>& env = {});

// `darkroom args...` in one process.
RunResult runAlone(const std::vector<std::string>& args);
// `mpirun -np ranks --oversubscribe darkroom args...`, allowed to run as root.
RunResult runOnRanks(int ranks, const std::vector<std::string>& args);

}  // namespace darkroom::test
