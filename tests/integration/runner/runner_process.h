#pragma once
// Runs the built `darkroom` executable and captures exit code, stdout, stderr.
#include <string>
#include <vector>

namespace darkroom::test {

struct ProcessResult {
    int exitCode = -1;
    std::string out;
    std::string err;
};

// `args` are passed verbatim (no shell); `env` entries are NAME=VALUE added to
// a copy of the environment with DARKROOM_PLUGIN_PATH cleared.
ProcessResult runDarkroom(const std::vector<std::string>& args, const std::vector<std::string>& env = {});

// As runDarkroom, without the power to read or write every file: as user
// and group 65534 (nobody) through setpriv when the test runs as root, so that
// permissions apply. Files the runner must reach need to be open to others.
ProcessResult runDarkroomUnprivileged(const std::vector<std::string>& args);
// Whether runDarkroomUnprivileged can start the runner at all: as root, the
// user nobody must be able to reach the build tree (a checkout inside a 0700
// folder, such as root's home or a mktemp folder, it cannot). "" when it
// can, else why not.
std::string whyUnprivilegedCannotRun();

// Starts the runner without waiting (output discarded); returns its pid.
int spawnDarkroom(const std::vector<std::string>& args);

}  // namespace darkroom::test
