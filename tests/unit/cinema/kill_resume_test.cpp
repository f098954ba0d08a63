// A capture killed with SIGKILL at any moment, then resumed, must leave the
// same database as an uninterrupted one; a second process must be locked out.
//
// The writing processes are this test executable started again: a static
// initialiser below sees DARKROOM_CINEMA_CHILD, does the child's work and
// exits before GoogleTest starts. (A plain fork() without exec could deadlock
// in a child of a process whose OpenImageIO/TBB threads held a lock.)
#include "cinema_test_data.h"
#include "test_support.h"

#include <darkroom/error.h>
#include <darkroom/data/cinema/writer.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <spawn.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

extern char** environ;

using namespace darkroom;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

namespace {

const std::vector<std::string> kColumns = {"phi", "theta"};
// Large enough that writing a product takes a noticeable time, so kills land
// inside writes too.
constexpr int kImageSize = 192;

// ---- the child ----------------------------------------------------------------

void signalParent(int fd) {
    const char byte = 'x';
    if (::write(fd, &byte, 1) != 1) std::_Exit(3);
}

// DARKROOM_CINEMA_CHILD = "write|hold <fd> <sleep-ms> <database>"
int childMain(const std::string& spec) {
    char mode[16] = {};
    int fd = -1, sleepMs = 0, consumed = 0;
    if (std::sscanf(spec.c_str(), "%15s %d %d %n", mode, &fd, &sleepMs, &consumed) < 3) return 2;
    const std::string db = spec.substr(std::size_t(consumed));
    try {
        CinemaWriter w(db, kColumns);
        signalParent(fd);  // ready: the lock is held
        if (std::string(mode) == "hold") {
            for (;;) ::pause();
        }
        for (const auto& p : test::gridEntries()) {
            w.addEntry(p, *test::gridImage(p, kImageSize));
            signalParent(fd);
            if (sleepMs) std::this_thread::sleep_for(std::chrono::milliseconds(sleepMs));
        }
        w.finish();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "child: %s\n", e.what());
        return 1;
    }
    return 0;
}

[[maybe_unused]] const bool kIsChild = [] {
    if (const char* spec = std::getenv("DARKROOM_CINEMA_CHILD")) std::_Exit(childMain(spec));
    return false;
}();

// ---- the parent ---------------------------------------------------------------

struct Child {
    pid_t pid = -1;
    int readFd = -1;
};

Child spawnChild(const std::string& mode, int sleepMs, const std::string& db) {
    int fds[2];
    if (::pipe(fds) != 0) throw Error("pipe failed");
    std::vector<std::string> env;
    for (char** e = environ; *e; ++e)
        if (std::string(*e).rfind("DARKROOM_CINEMA_CHILD=", 0) != 0) env.emplace_back(*e);
    env.push_back("DARKROOM_CINEMA_CHILD=" + mode + " " + std::to_string(fds[1]) + " " +
                  std::to_string(sleepMs) + " " + db);
    std::vector<char*> envp;
    for (auto& s : env) envp.push_back(s.data());
    envp.push_back(nullptr);
    const std::string exe = fs::read_symlink("/proc/self/exe").string();
    std::string arg0 = exe;
    char* argv[] = {arg0.data(), nullptr};
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addclose(&actions, fds[0]);
    Child c;
    const int rc = posix_spawn(&c.pid, exe.c_str(), &actions, nullptr, argv, envp.data());
    posix_spawn_file_actions_destroy(&actions);
    ::close(fds[1]);
    if (rc != 0) throw Error("posix_spawn failed");
    c.readFd = fds[0];
    return c;
}

// Blocks until the child has signalled `n` more times; false if it exited.
bool waitSignals(const Child& c, int n) {
    for (int i = 0; i < n; ++i) {
        char b;
        if (::read(c.readFd, &b, 1) != 1) return false;
    }
    return true;
}

int killAndReap(Child& c) {
    ::kill(c.pid, SIGKILL);
    int status = 0;
    ::waitpid(c.pid, &status, 0);
    ::close(c.readFd);
    return status;
}

// Relative path -> bytes of every file below `root`.
std::map<std::string, std::string> snapshot(const std::string& root) {
    std::map<std::string, std::string> out;
    for (const auto& e : fs::recursive_directory_iterator(root))
        if (e.is_regular_file())
            out[fs::relative(e.path(), root).string()] = test::readText(e.path().string());
    return out;
}

void resumeToTheEnd(const std::string& db) {
    CinemaWriterOptions o;
    o.resume = true;
    CinemaWriter w(db, kColumns, o);
    for (const auto& p : test::gridEntries())
        if (!w.hasEntry(p)) w.addEntry(p, *test::gridImage(p, kImageSize));
    w.finish();
}

std::map<std::string, std::string> referenceDatabase(const test::TempDir& dir) {
    const std::string ref = dir.file("reference.cdb");
    CinemaWriter w(ref, kColumns);
    for (const auto& p : test::gridEntries()) w.addEntry(p, *test::gridImage(p, kImageSize));
    w.finish();
    return snapshot(ref);
}

void expectSameDatabase(const std::map<std::string, std::string>& expected,
                        const std::map<std::string, std::string>& actual, const std::string& what) {
    std::vector<std::string> a, b;
    for (const auto& [k, v] : expected) a.push_back(k);
    for (const auto& [k, v] : actual) b.push_back(k);
    ASSERT_EQ(a, b) << what << ": different files";
    for (const auto& [name, bytes] : expected)
        EXPECT_TRUE(actual.at(name) == bytes) << what << ": " << name << " differs";
}

}  // namespace

TEST(CinemaKillResume, KilledBetweenEntriesThenResumedEqualsUninterrupted) {
    test::TempDir dir;
    const auto expected = referenceDatabase(dir);
    ASSERT_EQ(expected.size(), 22u);  // data.csv, the marker + 20 products, no lock file

    const std::string db = dir.file("killed.cdb");
    Child c = spawnChild("write", 50, db);
    ASSERT_TRUE(waitSignals(c, 1 + 7)) << "the child stopped early";
    killAndReap(c);
    // Mid-way: some entries written, not all, and the stale lock still there.
    const auto partial = snapshot(db);
    EXPECT_TRUE(partial.count(".lock"));
    const std::string csv = partial.at("data.csv");
    const auto rows = std::count(csv.begin(), csv.end(), '\n') - 1;
    EXPECT_GE(rows, 7);
    EXPECT_LT(rows, 20);

    resumeToTheEnd(db);
    expectSameDatabase(expected, snapshot(db), "kill after 7 entries");
}

TEST(CinemaKillResume, KilledAtArbitraryMomentsThenResumedEqualsUninterrupted) {
    test::TempDir dir;
    const auto expected = referenceDatabase(dir);
    // No pauses in the child: the kill lands wherever the writer happens to
    // be, often inside a product or data.csv write.
    int interrupted = 0;
    for (int delayMs : {0, 3, 10, 25, 50, 90, 150, 250}) {
        const std::string db = dir.file("killed-" + std::to_string(delayMs) + ".cdb");
        Child c = spawnChild("write", 0, db);
        ASSERT_TRUE(waitSignals(c, 1)) << "the child did not start";
        std::this_thread::sleep_for(std::chrono::milliseconds(delayMs));
        const int status = killAndReap(c);
        interrupted += WIFSIGNALED(status) ? 1 : 0;
        resumeToTheEnd(db);
        expectSameDatabase(expected, snapshot(db), "kill after " + std::to_string(delayMs) + " ms");
    }
    // Writing all 20 entries takes a few hundred ms here; the earlier kills
    // must have hit a running child, or this test proved nothing.
    EXPECT_GE(interrupted, 2);
}

TEST(CinemaKillResume, SecondProcessIsLockedOutUntilTheFirstDies) {
    test::TempDir dir;
    const std::string db = dir.file("locked.cdb");
    Child c = spawnChild("hold", 0, db);
    ASSERT_TRUE(waitSignals(c, 1));
    for (bool resume : {false, true}) {
        CinemaWriterOptions o;
        o.resume = resume;
        try {
            CinemaWriter w(db, kColumns, o);
            FAIL() << "a second writer must be refused";
        } catch (const Error& e) {
            EXPECT_THAT(e.what(), HasSubstr("database " + db + " is being written by another process (pid " +
                                            std::to_string(c.pid) + ")"));
        }
    }
    killAndReap(c);
    // The dead writer's lock file remains but is no longer locked.
    EXPECT_TRUE(fs::exists(db + "/.lock"));
    CinemaWriterOptions o;
    o.resume = true;
    CinemaWriter w(db, kColumns, o);
    EXPECT_EQ(w.entryCount(), 0u);
    w.finish();
    EXPECT_FALSE(fs::exists(db + "/.lock"));
}
