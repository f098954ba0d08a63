#include "run_process.h"

#include "test_support.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <filesystem>
#include <set>

extern char** environ;

namespace darkroom::test {

RunResult runProgram(const std::vector<std::string>& args, const std::vector<std::string>& env) {
    TempDir dir;
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 1, dir.file("out").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&actions, 2, dir.file("err").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    std::vector<std::string> argStore = args, envStore;
    for (char** e = environ; *e; ++e)
        if (std::string(*e).rfind("DARKROOM_PLUGIN_PATH=", 0) != 0) envStore.emplace_back(*e);
    envStore.insert(envStore.end(), env.begin(), env.end());
    std::vector<char*> argv, envp;
    for (auto& a : argStore) argv.push_back(a.data());
    for (auto& e : envStore) envp.push_back(e.data());
    argv.push_back(nullptr);
    envp.push_back(nullptr);
    RunResult r;
    pid_t pid = 0;
    if (posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), envp.data()) == 0) {
        int status = 0;
        waitpid(pid, &status, 0);
        r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    }
    posix_spawn_file_actions_destroy(&actions);
    r.out = readText(dir.file("out"));
    r.err = readText(dir.file("err"));
    return r;
}

RunResult runAlone(const std::vector<std::string>& args) {
    std::vector<std::string> argv{DARKROOM_RUNNER};
    argv.insert(argv.end(), args.begin(), args.end());
    return runProgram(argv);
}

RunResult runOnRanks(int ranks, const std::vector<std::string>& args) {
    std::vector<std::string> argv{DARKROOM_MPIEXEC, "-np", std::to_string(ranks), "--oversubscribe", DARKROOM_RUNNER};
    argv.insert(argv.end(), args.begin(), args.end());
    return runProgram(argv, {"OMPI_ALLOW_RUN_AS_ROOT=1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1"});
}


}  // namespace darkroom::test
