// Where Movie writes (issue 26): a write that fails (a full disk, reproduced
// with a file size limit) is an error naming the node and the file, with the
// temporary removed — it once crashed; temporaries of killed runs are removed,
// only those of this movie whose process is gone; `path` is a file, never an
// FFmpeg URL (pipe:1 wrote to stdout), and stays inside the output folder.
#include "decoded_movie.h"
#include "test_support.h"

#include <darkroom/error.h>
#include <darkroom/data/image_io.h>
#include <darkroom/core/run_filter.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <fcntl.h>
#include <functional>
#include <filesystem>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace darkroom;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

namespace {

using Inputs = std::map<std::string, std::vector<Value>>;

// Frames of noise (they do not compress: the movie grows by tens of KB a frame).
std::string noiseDatabase(const test::TempDir& dir, int frames) {
    const std::string db = dir.file("frames.cdb");
    fs::create_directories(db);
    std::string csv = "time,FILE\n";
    unsigned seed = 12345;
    for (int t = 0; t < frames; ++t) {
        const std::string name = "t" + std::to_string(t) + ".png";
        writeImage(*test::makeImage(128, 128, {"R", "G", "B"}, [&](int, int, int) {
            seed = seed * 1664525u + 1013904223u;
            return float(seed >> 8) / float(1 << 24);
        }), db + "/" + name);
        csv += std::to_string(t) + "," + name + "\n";
    }
    test::writeText(db + "/data.csv", csv);
    return db;
}

FilterRunResult makeMovie(const std::string& db, const std::string& path, const std::string& outputDir = "") {
    auto f = test::pluginRegistry().createFilter("Movie");
    FilterRunOptions o;
    o.outputDir = outputDir;
    o.nodeType = "Movie";
    return runFilter(*f, {{"database", {Value(db)}}, {"path", {Value(path)}}, {"preset", {Value("ultrafast")}}}, o);
}

std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

std::vector<std::string> filesIn(const std::string& folder) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(folder)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

// A file size limit for this process while it lives, SIGXFSZ ignored so that
// a write past it fails with EFBIG (as on a full disk) instead of killing us.
class FileSizeLimit {
public:
    explicit FileSizeLimit(rlim_t bytes) {
        getrlimit(RLIMIT_FSIZE, &old_);
        oldHandler_ = std::signal(SIGXFSZ, SIG_IGN);
        rlimit r = old_;
        r.rlim_cur = bytes;
        setrlimit(RLIMIT_FSIZE, &r);
    }
    ~FileSizeLimit() {
        setrlimit(RLIMIT_FSIZE, &old_);
        std::signal(SIGXFSZ, oldHandler_);
    }

private:
    rlimit old_{};
    void (*oldHandler_)(int) = nullptr;
};

// The pid of a process that has exited (and was reaped).
pid_t deadPid() {
    pid_t pid = -1;
    char arg0[] = "true";
    char* argv[] = {arg0, nullptr};
    EXPECT_EQ(posix_spawnp(&pid, "true", nullptr, nullptr, argv, environ), 0);
    int status = 0;
    waitpid(pid, &status, 0);
    return pid;
}

// Runs `f` with stdout going to a file; returns what was written there.
std::string stdoutOf(const std::function<void()>& f, const std::string& capture) {
    std::fflush(stdout);
    const int saved = dup(1);
    const int fd = open(capture.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(fd, 1);
    close(fd);
    try {
        f();
    } catch (...) {
        std::fflush(stdout);
        dup2(saved, 1);
        close(saved);
        throw;
    }
    std::fflush(stdout);
    dup2(saved, 1);
    close(saved);
    return test::readText(capture);
}

// Runs `f` in `folder` as the working directory.
void inFolder(const std::string& folder, const std::function<void()>& f) {
    const fs::path before = fs::current_path();
    fs::current_path(folder);
    try {
        f();
    } catch (...) {
        fs::current_path(before);
        throw;
    }
    fs::current_path(before);
}

}  // namespace

TEST(MovieOutput, AFailedWriteIsAClearErrorAndLeavesNoTemporary) {
    test::TempDir dir;
    const std::string db = noiseDatabase(dir, 6);
    makeMovie(db, "talk.mp4", dir.file("full"));
    ASSERT_EQ(test::decodeMovie(dir.file("full/talk.mp4")).frames(), 6);
    const auto size = rlim_t(fs::file_size(dir.file("full/talk.mp4")));  // about 80 KB
    ASSERT_GT(size, 20000u);
    const std::string out = dir.file("out");
    fs::create_directories(out);
    // The disk fills at the start, among the frames, and while the index is
    // moved to the front (faststart rewrites the file).
    for (const rlim_t bytes : {rlim_t(2000), size / 2, size - 1000}) {
        std::string e;
        {
            const FileSizeLimit limit(bytes);
            e = errorOf([&] { makeMovie(db, "talk.mp4", out); });
        }
        EXPECT_THAT(e, HasSubstr("node 'runFilter' (Movie)")) << bytes;
        EXPECT_THAT(e, HasSubstr("movie " + out + "/talk.mp4: ")) << bytes;
        EXPECT_THAT(e, HasSubstr("File too large")) << bytes;
        EXPECT_TRUE(filesIn(out).empty()) << bytes << ": " << ::testing::PrintToString(filesIn(out));
    }
}

TEST(MovieOutput, TemporariesOfKilledRunsAreRemovedOnlyWhenTheirProcessIsGone) {
    test::TempDir dir;
    const std::string db = noiseDatabase(dir, 2);
    const std::string out = dir.file("out");
    fs::create_directories(out);
    const std::string dead = std::to_string(deadPid()), alive = std::to_string(getpid());
    const std::vector<std::string> kept = {
        "talk.tmp-" + alive + "-3.mp4",   // a live process's (this one's)
        "talk.tmp-" + dead + "-0.mp4.x",  // not the pattern
        "talk.tmp-" + dead + "-x.mp4",
        "talk.tmp-" + dead + ".mp4",
        "other.tmp-" + dead + "-0.mp4",   // another movie's
        "talk.tmp-1-0.mp4",               // init's
    };
    for (const auto& name : kept) test::writeText(out + "/" + name, "partial");
    test::writeText(out + "/talk.tmp-" + dead + "-0.mp4", "partial");
    fs::create_directories(out + "/talk.tmp-" + dead + "-1.mp4");  // a folder is never removed
    const auto r = makeMovie(db, "talk.mp4", out);
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_THAT(r.warnings[0], HasSubstr("talk.tmp-" + dead + "-0.mp4"));
    EXPECT_FALSE(fs::exists(out + "/talk.tmp-" + dead + "-0.mp4"));
    for (const auto& name : kept) EXPECT_TRUE(fs::exists(out + "/" + name)) << name;
    EXPECT_TRUE(fs::is_directory(out + "/talk.tmp-" + dead + "-1.mp4"));
    EXPECT_EQ(test::decodeMovie(out + "/talk.mp4").frames(), 2);
}

TEST(MovieOutput, PathsAreFilesNotFfmpegUrls) {
    test::TempDir dir;
    const std::string db = noiseDatabase(dir, 2);
    fs::create_directories(dir.file("run"));
    // No output folder and no pipeline folder: paths relative to the working directory.
    std::string printed;
    inFolder(dir.file("run"), [&] {
        printed = stdoutOf([&] { makeMovie(db, "pipe:1"); }, dir.file("stdout"));
        makeMovie(db, "file:../x.mp4");
    });
    EXPECT_TRUE(printed.empty()) << printed.size() << " bytes on stdout";
    EXPECT_EQ(test::decodeMovie(dir.file("run/pipe:1")).frames(), 2);
    EXPECT_EQ(test::decodeMovie(dir.file("run/file:../x.mp4")).frames(), 2);
    EXPECT_FALSE(fs::exists(dir.file("x.mp4")));
    EXPECT_EQ(filesIn(dir.file("run")), (std::vector<std::string>{"file:..", "pipe:1"}));
}

TEST(MovieOutput, WithAnOutputFolderPathsStayInsideIt) {
    test::TempDir dir;
    const std::string db = noiseDatabase(dir, 2);
    const std::string out = dir.file("out");
    fs::create_directories(out + "/sub");
    fs::create_directories(dir.file("elsewhere"));
    fs::create_directory_symlink(dir.file("elsewhere"), out + "/link");
    for (const std::string& path : {std::string("../escape.mp4"), std::string("sub/../../escape.mp4"),
                                    dir.file("escape.mp4"), std::string("link/escape.mp4"), std::string(".")}) {
        const std::string e = errorOf([&] { makeMovie(db, path, out); });
        EXPECT_THAT(e, HasSubstr("path '" + path + "' is not a file inside the output folder")) << path;
        EXPECT_THAT(e, HasSubstr("node 'runFilter' (Movie)")) << path;
    }
    EXPECT_FALSE(fs::exists(dir.file("escape.mp4")));
    EXPECT_TRUE(fs::is_empty(dir.file("elsewhere")));
    // Inside it, in a sub-folder or through "..", absolute or not: written.
    makeMovie(db, "sub/../a.mp4", out);
    makeMovie(db, out + "/sub/b.mp4", out);
    EXPECT_EQ(test::decodeMovie(out + "/a.mp4").frames(), 2);
    EXPECT_EQ(test::decodeMovie(out + "/sub/b.mp4").frames(), 2);
}
