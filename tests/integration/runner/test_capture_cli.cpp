// `darkroom capture` and `darkroom info` end to end: the bunny from
// ../shared/data, and a capture killed with SIGKILL then resumed, which must
// give the same database, byte for byte, as an uninterrupted one.
#include "runner_process.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <sys/wait.h>
#include <thread>

namespace fs = std::filesystem;
using namespace darkroom;
using darkroom::test::runDarkroom;

namespace {

std::map<std::string, std::string> folderBytes(const std::string& dir) {
    std::map<std::string, std::string> out;
    for (const auto& f : fs::directory_iterator(dir))
        if (f.is_regular_file()) out[f.path().filename().string()] = test::readText(f.path().string());
    return out;
}

std::size_t countExr(const std::string& dir) {
    std::size_t n = 0;
    std::error_code ec;
    for (const auto& f : fs::directory_iterator(dir, ec))
        if (f.path().extension() == ".exr" && f.path().filename().string().find(".tmp-") == std::string::npos) ++n;
    return n;
}

const char* kScene = R"(objects:
  - generator: isosurface
    parameters: {resolution: 48}
cameras:
  resolution: [160, 120]
  grid: {phi: 12, theta: [-30, 0, 30]}
channels:
  scalars: [height]
  normals: true
)";

}  // namespace

TEST(CaptureCli, BunnyCaptureIsDescribedByInfo) {
    const std::string bunny = test::sharedData("meshes/stanford-bunny.obj");
    if (bunny.empty()) GTEST_SKIP() << "../shared/data is absent";
    test::TempDir dir;
    test::writeText(dir.file("bunny.yaml"), "objects:\n  - file: " + bunny +
                                                "\ncameras:\n  resolution: [64, 48]\n  grid: {phi: 3, theta: 1}\n"
                                                "channels:\n  normals: true\n");
    const auto cap = runDarkroom({"capture", dir.file("bunny.yaml"), "--output", dir.file("bunny.cdb")});
    ASSERT_EQ(cap.exitCode, 0) << cap.err;
    const auto info = runDarkroom({"info", dir.file("bunny.cdb")});
    ASSERT_EQ(info.exitCode, 0) << info.err;
    EXPECT_NE(info.out.find("3 rows"), std::string::npos) << info.out;
    EXPECT_NE(info.out.find("64 x 48"), std::string::npos) << info.out;
    EXPECT_NE(info.out.find("Z (float32)"), std::string::npos) << info.out;
    EXPECT_NE(info.out.find("N.x"), std::string::npos) << info.out;
    EXPECT_NE(info.out.find("perspective"), std::string::npos) << info.out;
}

TEST(CaptureCli, RefusesToOverwriteWithoutAFlag) {
    test::TempDir dir;
    test::writeText(dir.file("s.yaml"), kScene);
    ASSERT_EQ(runDarkroom({"capture", dir.file("s.yaml"), "-o", dir.file("db.cdb")}).exitCode, 0);
    const auto again = runDarkroom({"capture", dir.file("s.yaml"), "-o", dir.file("db.cdb")});
    EXPECT_EQ(again.exitCode, 2);
    EXPECT_NE(again.err.find("--overwrite"), std::string::npos) << again.err;
    EXPECT_EQ(runDarkroom({"capture", dir.file("s.yaml"), "-o", dir.file("db.cdb"), "--overwrite"}).exitCode, 0);
}

TEST(CaptureCli, BadSceneFileExit2WithPosition) {
    test::TempDir dir;
    test::writeText(dir.file("s.yaml"), "objects:\n  - generator: isosurface\n    colour: red\n");
    const auto r = runDarkroom({"capture", dir.file("s.yaml"), "-o", dir.file("db.cdb")});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find(dir.file("s.yaml") + ":3:"), std::string::npos) << r.err;
}

TEST(CaptureCli, KilledThenResumedEqualsUninterrupted) {
    test::TempDir dir;
    test::writeText(dir.file("s.yaml"), kScene);
    ASSERT_EQ(runDarkroom({"capture", dir.file("s.yaml"), "-o", dir.file("whole.cdb"), "-j", "1"}).exitCode, 0);
    const auto whole = folderBytes(dir.file("whole.cdb"));
    ASSERT_EQ(countExr(dir.file("whole.cdb")), 36u);

    const std::string db = dir.file("killed.cdb");
    const int pid = test::spawnDarkroom({"capture", dir.file("s.yaml"), "-o", db, "-j", "1"});
    ASSERT_GT(pid, 0);
    // Kill it mid-way: after a few entries, well before the end.
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (countExr(db) < 5 && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    ::kill(pid, SIGKILL);
    int status = 0;
    ::waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFSIGNALED(status)) << "the capture finished before it could be killed";
    ASSERT_LT(countExr(db), 36u);

    const auto resumed = runDarkroom({"capture", dir.file("s.yaml"), "-o", db, "--resume"});
    ASSERT_EQ(resumed.exitCode, 0) << resumed.err;
    const auto after = folderBytes(db);
    ASSERT_EQ(after.size(), whole.size());
    for (const auto& [name, bytes] : whole) {
        ASSERT_TRUE(after.count(name)) << name;
        EXPECT_TRUE(after.at(name) == bytes) << name << " differs";
    }
}

TEST(CaptureCli, RunForeachWritesOneOutputPerEntry) {
    test::TempDir dir;
    test::writeText(dir.file("s.yaml"), "objects:\n  - generator: isosurface\n    parameters: {resolution: 24}\n"
                                        "cameras:\n  resolution: [32, 24]\n  grid: {phi: 4, theta: 1}\n");
    ASSERT_EQ(runDarkroom({"capture", dir.file("s.yaml"), "-o", dir.file("db.cdb")}).exitCode, 0);
    test::writeText(dir.file("p.yaml"), R"(darkroom: 1
nodes:
  reader:
    type: CinemaReader
    parameters:
      database: db.cdb
  colour:
    type: ColorMapping
    parameters:
      channel: height
  write:
    type: ImageWriter
    parameters:
      path: frames/view.png
edges:
  - reader.image -> colour.image
  - colour.image -> write.image
)");
    const auto all = runDarkroom({"run", dir.file("p.yaml"), "--foreach", "reader", "-o", dir.file("out")});
    ASSERT_EQ(all.exitCode, 0) << all.err;
    std::vector<std::string> names;
    for (const auto& f : fs::directory_iterator(dir.file("out/frames"))) names.push_back(f.path().filename().string());
    std::sort(names.begin(), names.end());
    EXPECT_EQ(names, (std::vector<std::string>{"view_phi=-180_theta=0.png", "view_phi=-90_theta=0.png",
                                               "view_phi=0_theta=0.png", "view_phi=90_theta=0.png"}));
    const auto some = runDarkroom({"run", dir.file("p.yaml"), "--foreach", "reader", "--where", "phi > 0", "-o",
                                   dir.file("sql")});
    ASSERT_EQ(some.exitCode, 0) << some.err;
    EXPECT_TRUE(fs::exists(dir.file("sql/frames/view_phi=90_theta=0.png")));
    EXPECT_EQ(std::distance(fs::directory_iterator(dir.file("sql/frames")), fs::directory_iterator{}), 1);
    EXPECT_EQ(runDarkroom({"run", dir.file("p.yaml"), "--foreach", "colour"}).exitCode, 2);
}
