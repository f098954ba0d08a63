#include "runner_process.h"

#include "test_support.h"

#include <cstdlib>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace darkroom::test {

std::string whyUnprivilegedCannotRun() {
    const ProcessResult r = runDarkroomUnprivileged({"--version"});
    if (r.exitCode == 0) return "";
    return "the user nobody cannot start " + std::string(DARKROOM_RUNNER) + " (exit " + std::to_string(r.exitCode) +
           ": " + r.err + "); a folder on the way is not searchable by others, e.g. a 0700 home or mktemp folder";
}

namespace {

ProcessResult runWithPrefix(const std::vector<std::string>& prefix, const std::vector<std::string>& args,
                            const std::vector<std::string>& env);

}  // namespace

ProcessResult runDarkroom(const std::vector<std::string>& args, const std::vector<std::string>& env) {
    return runWithPrefix({}, args, env);
}

ProcessResult runDarkroomUnprivileged(const std::vector<std::string>& args) {
    if (::geteuid() != 0) return runWithPrefix({}, args, {});
    return runWithPrefix({"/usr/bin/setpriv", "--reuid=65534", "--regid=65534", "--clear-groups", "--"}, args, {});
}

namespace {

ProcessResult runWithPrefix(const std::vector<std::string>& prefix, const std::vector<std::string>& args,
                            const std::vector<std::string>& env) {
    TempDir dir;
    const std::string outPath = dir.file("out"), errPath = dir.file("err");
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, 1, outPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&fa, 2, errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);

    std::vector<std::string> argStore = prefix;
    argStore.push_back(DARKROOM_RUNNER);
    argStore.insert(argStore.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : argStore) argv.push_back(a.data());
    argv.push_back(nullptr);

    std::vector<std::string> envStore;
    for (char** e = environ; *e; ++e)
        if (std::string(*e).rfind("DARKROOM_PLUGIN_PATH=", 0) != 0) envStore.emplace_back(*e);
    envStore.insert(envStore.end(), env.begin(), env.end());
    std::vector<char*> envp;
    for (auto& e : envStore) envp.push_back(e.data());
    envp.push_back(nullptr);

    pid_t pid = 0;
    ProcessResult r;
    if (posix_spawn(&pid, argv[0], &fa, nullptr, argv.data(), envp.data()) == 0) {
        int status = 0;
        waitpid(pid, &status, 0);
        r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    }
    posix_spawn_file_actions_destroy(&fa);
    r.out = readText(outPath);
    r.err = readText(errPath);
    return r;
}

}  // namespace

int spawnDarkroom(const std::vector<std::string>& args) {
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
    std::vector<std::string> argStore = {DARKROOM_RUNNER};
    argStore.insert(argStore.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : argStore) argv.push_back(a.data());
    argv.push_back(nullptr);
    pid_t pid = -1;
    if (posix_spawn(&pid, argv[0], &fa, nullptr, argv.data(), environ) != 0) pid = -1;
    posix_spawn_file_actions_destroy(&fa);
    return pid;
}

}  // namespace darkroom::test
