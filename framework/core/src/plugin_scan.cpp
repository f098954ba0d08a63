#include "plugin_scan.h"

#include <darkroom/atomic_file.h>
#include <darkroom/version.h>

#include <dlfcn.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

extern char** environ;

namespace darkroom {

namespace fs = std::filesystem;

namespace {

// The probe lives in the bin/ folder beside the lib/ folder that holds this
// library, in the build tree and in an installation alike.
std::string findProbe() {
    if (const char* env = std::getenv("DARKROOM_PLUGIN_PROBE")) return env;
    Dl_info info{};
    if (::dladdr(reinterpret_cast<void*>(&findProbe), &info) && info.dli_fname) {
        std::error_code ec;
        const fs::path lib = fs::weakly_canonical(info.dli_fname, ec).parent_path();
        for (const fs::path& candidate : {lib / ".." / "bin" / "darkroom-plugin-probe", lib / "darkroom-plugin-probe"})
            if (fs::is_regular_file(candidate, ec)) return candidate.lexically_normal().string();
    }
    return {};
}

bool stamp(const std::string& path, std::int64_t& mtimeNs, std::uintmax_t& size) {
    std::error_code ec;
    const auto t = fs::last_write_time(path, ec);
    if (ec) return false;
    size = fs::file_size(path, ec);
    if (ec) return false;
    mtimeNs = std::chrono::duration_cast<std::chrono::nanoseconds>(t.time_since_epoch()).count();
    return true;
}

std::string signalName(int sig) {
    const char* d = ::strsignal(sig);
    return "signal " + std::to_string(sig) + (d ? std::string(" (") + d + ")" : std::string());
}

}  // namespace

ProbeVerdict runProbe(const std::string& probe, const std::string& plugin, double timeoutSeconds) {
    int out[2];
    if (::pipe2(out, O_CLOEXEC) != 0) return {true, ""};  // cannot isolate: load in-process as before
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
    std::string a0 = probe, a1 = plugin;
    char* argv[] = {a0.data(), a1.data(), nullptr};
    pid_t pid = -1;
    const int rc = ::posix_spawn(&pid, probe.c_str(), &actions, nullptr, argv, environ);
    posix_spawn_file_actions_destroy(&actions);
    ::close(out[1]);
    if (rc != 0) {
        ::close(out[0]);
        return {true, ""};
    }
    std::string text;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeoutSeconds);
    bool timedOut = false;
    for (;;) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) {
            timedOut = true;
            break;
        }
        pollfd p{out[0], POLLIN, 0};
        const int n = ::poll(&p, 1, int(left.count()));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) continue;
        char buf[512];
        const ssize_t got = ::read(out[0], buf, sizeof buf);
        if (got <= 0) break;
        text.append(buf, std::size_t(got));
    }
    ::close(out[0]);
    if (timedOut) ::kill(pid, SIGKILL);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (timedOut)
        return {false, "it did not finish loading within " + std::to_string(int(timeoutSeconds)) + " s (a hang in a "
                       "static constructor or in registration?)"};
    if (WIFSIGNALED(status)) return {false, "it crashed while loading or registering: " + signalName(WTERMSIG(status))};
    if (text.rfind("ok", 0) == 0) return {true, "", typesSaid(text)};
    if (text.rfind("refused: ", 0) == 0) {
        std::string why = text.substr(9);
        while (!why.empty() && (why.back() == '\n' || why.back() == '\r')) why.pop_back();
        return {false, why};
    }
    return {false, "it ended the process while loading (exit status " +
                       std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) +
                       ", e.g. exit() in a static constructor)"};
}

namespace {

// "a,b,c" -> {a, b, c}; "" -> {}.
std::vector<std::string> splitTypes(const std::string& list) {
    std::vector<std::string> out;
    std::stringstream ss(list);
    for (std::string t; std::getline(ss, t, ',');)
        if (!t.empty()) out.push_back(t);
    return out;
}

std::string joinTypes(const std::vector<std::string>& types) {
    std::string out;
    for (const auto& t : types) out += (out.empty() ? "" : ",") + t;
    return out;
}

constexpr const char* kTypesField = "types=";
constexpr const char* kTypesUnlisted = "types?";  // probed, but the types could not be listed

}  // namespace

std::optional<std::vector<std::string>> typesSaid(const std::string& probeOutput) {
    // "ok\tTypeA,TypeB,backend:embree\n"; a bare "ok" (an older probe, or a
    // plugin the host refuses by itself) says nothing of its types.
    const std::size_t tab = probeOutput.find('\t');
    if (tab == std::string::npos || probeOutput.compare(0, tab, "ok") != 0) return std::nullopt;
    std::string list = probeOutput.substr(tab + 1);
    while (!list.empty() && (list.back() == '\n' || list.back() == '\r')) list.pop_back();
    return splitTypes(list);
}

std::string PluginScan::cachePath() {
    if (const char* env = std::getenv("DARKROOM_PLUGIN_CACHE")) return env;
    const std::string name = "plugin-scan-abi" + std::to_string(DARKROOM_ABI_VERSION) + ".tsv";
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return (fs::path(xdg) / "darkroom" / name).string();
    if (const char* home = std::getenv("HOME"); home && *home)
        return (fs::path(home) / ".cache" / "darkroom" / name).string();
    return {};
}

PluginScan::PluginScan() : probe_(findProbe()), cacheFile_(cachePath()) {
    if (cacheFile_.empty()) return;
    std::ifstream in(cacheFile_);
    std::string line;
    // path \t mtime \t size \t ok|quarantined \t reason [\t types=A,B,...]
    while (std::getline(in, line)) {
        std::vector<std::string> f;
        std::stringstream ss(line);
        std::string x;
        while (std::getline(ss, x, '\t')) f.push_back(x);
        if (f.size() < 4) continue;
        Entry e;
        try {
            e.mtimeNs = std::stoll(f[1]);
            e.size = std::stoull(f[2]);
        } catch (...) {
            continue;
        }
        e.verdict.ok = f[3] == "ok";
        e.verdict.reason = f.size() > 4 ? f[4] : "";
        if (f.size() > 5 && f[5].rfind(kTypesField, 0) == 0)
            e.verdict.types = splitTypes(f[5].substr(std::string(kTypesField).size()));
        e.typesAsked = e.verdict.types || (f.size() > 5 && f[5] == kTypesUnlisted);
        entries_[f[0]] = e;
    }
}

ProbeVerdict PluginScan::check(const std::string& path) {
    if (probe_.empty()) return {true, ""};
    std::int64_t mtime = 0;
    std::uintmax_t size = 0;
    if (!stamp(path, mtime, size)) return {true, ""};  // the in-process loader reports the problem
    std::error_code ec;
    const std::string key = fs::weakly_canonical(path, ec).string();
    // A verdict of a cache written before types were recorded is probed
    // again, once, to learn them.
    if (auto it = entries_.find(key); it != entries_.end() && it->second.mtimeNs == mtime &&
                                      it->second.size == size && (!it->second.verdict.ok || it->second.typesAsked))
        return it->second.verdict;
    Entry e;
    e.mtimeNs = mtime;
    e.size = size;
    e.verdict = runProbe(probe_, path, 20.0);
    e.typesAsked = true;
    entries_[key] = e;
    dirty_ = true;
    return e.verdict;
}

void PluginScan::save() {
    if (!dirty_ || cacheFile_.empty()) return;
    std::string text;
    for (const auto& [path, e] : entries_) {
        std::string reason = e.verdict.reason;
        for (char& c : reason)
            if (c == '\t' || c == '\n') c = ' ';
        text += path + "\t" + std::to_string(e.mtimeNs) + "\t" + std::to_string(e.size) + "\t" +
                (e.verdict.ok ? "ok" : "quarantined") + "\t" + reason +
                (e.verdict.types ? "\t" + std::string(kTypesField) + joinTypes(*e.verdict.types)
                 : e.typesAsked  ? "\t" + std::string(kTypesUnlisted)
                                 : std::string()) +
                "\n";
    }
    std::error_code ec;
    fs::create_directories(fs::path(cacheFile_).parent_path(), ec);
    try {
        writeFileAtomic(cacheFile_, text);
        dirty_ = false;
    } catch (...) {
        // A cache that cannot be written only costs a probe next time.
    }
}

}  // namespace darkroom
