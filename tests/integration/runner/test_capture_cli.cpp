// `darkroom capture` and `darkroom info` end to end: the bunny from
// ../shared/data, and a capture killed with SIGKILL then resumed, which must
// give the same database, byte for byte, as an uninterrupted one.
#include "file_size_limit.h"
#include "runner_process.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
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

// A scene drawing an STL (ASCII) and an OFF file, captured end to end: a
// tetrahedron in each format, side by side.
TEST(CaptureCli, StlAndOffScenesCapture) {
    test::TempDir dir;
    const char* corners[4] = {"0 0 0", "1 0 0", "0 1 0", "0 0 1"};
    const char* shifted[4] = {"2 0 0", "3 0 0", "2 1 0", "2 0 1"};  // the OFF's, beside the STL's
    const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    std::string stl = "solid tetra\n", off = "OFF\n4 4 6\n";
    for (const char* c : shifted) off += std::string(c) + "\n";
    for (const auto& f : faces) {
        stl += "facet normal 0 0 0\nouter loop\n";
        for (int v : f) stl += std::string("vertex ") + corners[v] + "\n";
        stl += "endloop\nendfacet\n";
        off += "3 " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " + std::to_string(f[2]) + "\n";
    }
    test::writeText(dir.file("tetra.stl"), stl + "endsolid tetra\n");
    test::writeText(dir.file("tetra.off"), off);
    test::writeText(dir.file("s.yaml"), "objects:\n  - file: tetra.stl\n  - file: tetra.off\n    name: other\n"
                                        "cameras:\n  resolution: [32, 24]\n  grid: {phi: 2, theta: 1}\n"
                                        "channels:\n  normals: true\n  objectId: true\n");
    const auto cap = runDarkroom({"capture", dir.file("s.yaml"), "--output", dir.file("db.cdb")});
    ASSERT_EQ(cap.exitCode, 0) << cap.err;
    const auto info = runDarkroom({"info", dir.file("db.cdb")});
    ASSERT_EQ(info.exitCode, 0) << info.err;
    EXPECT_NE(info.out.find("2 rows"), std::string::npos) << info.out;
    EXPECT_NE(info.out.find("32 x 24"), std::string::npos) << info.out;
    EXPECT_NE(info.out.find("N.x"), std::string::npos) << info.out;
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

// A product whose write fails (here: past RLIMIT_FSIZE, EFBIG; on a cluster:
// EIO, a quota, NFS) stops the capture with an error naming the file, and
// data.csv never lists it.
TEST(CaptureCli, AFailedProductWriteExitsNonZeroAndIsNeverListed) {
    test::TempDir dir;
    test::writeText(dir.file("s.yaml"), kScene);
    const std::string db = dir.file("db.cdb");
    test::ProcessResult r;
    {
        test::FileSizeLimit limit(4096);  // data.csv and the marker fit, a product does not
        r = runDarkroom({"capture", dir.file("s.yaml"), "-o", db, "-j", "1"});
    }
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.err.find("cannot write '" + db + "/phi="), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(std::strerror(EFBIG)), std::string::npos) << r.err;
    EXPECT_EQ(test::readText(db + "/data.csv"), "phi,theta,FILE\n");
    std::vector<std::string> left;
    for (const auto& f : fs::directory_iterator(db)) left.push_back(f.path().filename().string());
    std::sort(left.begin(), left.end());
    EXPECT_EQ(left, (std::vector<std::string>{".darkroom-database", "data.csv"}));  // no product, lock or temporary
}

TEST(CaptureCli, ResumeRefusesAChangedSceneNamingTheChange) {
    test::TempDir dir;
    const std::string scene = "objects:\n  - generator: isosurface\n    parameters: {resolution: 16}\n"
                              "cameras:\n  resolution: [64, 64]\n  grid: {phi: 3, theta: 1}\n";
    test::writeText(dir.file("s.yaml"), scene);
    const std::string db = dir.file("db.cdb");
    ASSERT_EQ(runDarkroom({"capture", dir.file("s.yaml"), "-o", db}).exitCode, 0);
    const auto before = folderBytes(db);
    std::string smaller = scene;
    smaller.replace(smaller.find("[64, 64]"), 8, "[32, 32]");
    test::writeText(dir.file("s.yaml"), smaller);
    const auto r = runDarkroom({"capture", dir.file("s.yaml"), "-o", db, "--resume"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("cannot resume " + db +
                         ": the scene file changed since the capture began (resolution 64x64 \u2192 32x32)"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(folderBytes(db), before);
    EXPECT_FALSE(fs::exists(db + "/.lock"));
    // Another option, the same scene: named too.
    test::writeText(dir.file("s.yaml"), scene);
    const auto piz = runDarkroom({"capture", dir.file("s.yaml"), "-o", db, "--resume", "--compression", "piz"});
    EXPECT_EQ(piz.exitCode, 2);
    EXPECT_NE(piz.err.find("the capture options changed since the capture began (compression zip \u2192 piz)"),
              std::string::npos)
        << piz.err;
    // The unchanged scene resumes (and has nothing left to do).
    const auto same = runDarkroom({"capture", dir.file("s.yaml"), "-o", db, "--resume"});
    EXPECT_EQ(same.exitCode, 0) << same.err;
    EXPECT_EQ(folderBytes(db), before);
}

// Geometric and smooth normals do not mix in one database: the style is part
// of the channels a resume compares. Geometric keeps the name databases had
// before smooth normals, so those still resume with `normals: geometric`.
TEST(CaptureCli, ResumeRefusesAnotherNormalsStyle) {
    test::TempDir dir;
    const std::string scene = "objects:\n  - generator: isosurface\n    parameters: {resolution: 16}\n"
                              "cameras:\n  resolution: [32, 32]\n  grid: {phi: 2, theta: 1}\n"
                              "channels: {normals: geometric}\n";
    test::writeText(dir.file("s.yaml"), scene);
    const std::string db = dir.file("db.cdb");
    ASSERT_EQ(runDarkroom({"capture", dir.file("s.yaml"), "-o", db}).exitCode, 0);
    EXPECT_NE(test::readText(db + "/.darkroom-database").find("normals"), std::string::npos);
    std::string smooth = scene;
    smooth.replace(smooth.find("geometric"), 9, "true");
    test::writeText(dir.file("s.yaml"), smooth);
    const auto r = runDarkroom({"capture", dir.file("s.yaml"), "-o", db, "--resume"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("magnitude,normals \u2192 height,field,gradient magnitude,smooth normals (feature angle 30))"),
              std::string::npos)
        << r.err;
}

// The meshes a scene names are part of what --resume compares (by name, size
// and modification time): a scene file unchanged byte for byte whose mesh was
// replaced used to resume, mixing the old mesh's products with the new one's.
TEST(CaptureCli, ResumeRefusesAChangedMeshNamingIt) {
    test::TempDir dir;
    const std::string triangle = "v -1 -1 0\nv 1 -1 0\nv 0 1 0\nf 1 2 3\n";
    test::writeText(dir.file("mesh.obj"), triangle);
    // Fixed cameras: nothing but the mesh can tell the two captures apart.
    test::writeText(dir.file("s.yaml"), "objects:\n  - file: mesh.obj\n"
                                        "cameras:\n  resolution: [16, 16]\n  list:\n"
                                        "    - {position: [0, 0, 5], target: [0, 0, 0]}\n"
                                        "    - {position: [5, 0, 0], target: [0, 0, 0]}\n");
    const std::string db = dir.file("db.cdb");
    ASSERT_EQ(runDarkroom({"capture", dir.file("s.yaml"), "-o", db}).exitCode, 0);
    const auto before = folderBytes(db);
    EXPECT_NE(before.at(".darkroom-database").find("the mesh and volume files the scene reads"), std::string::npos);
    // Unchanged: resumes, nothing to do.
    ASSERT_EQ(runDarkroom({"capture", dir.file("s.yaml"), "-o", db, "--resume"}).exitCode, 0);
    EXPECT_EQ(folderBytes(db), before);
    // The mesh grows by a second triangle inside the first one's bounds (so the
    // cameras, placed from the bounds, do not move); the scene file is the same.
    test::writeText(dir.file("mesh.obj"), triangle + "v 0 0 0\nf 1 2 4\n");
    const auto r = runDarkroom({"capture", dir.file("s.yaml"), "-o", db, "--resume"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("cannot resume " + db + ": the mesh and volume files the scene reads changed since the "
                         "capture began (name, size and time 1 file "),
              std::string::npos)
        << r.err;
    EXPECT_EQ(folderBytes(db), before);
    EXPECT_FALSE(fs::exists(db + "/.lock"));
}

TEST(CaptureCli, OverwriteRemovesOnlyItsOwnFilesAndRefusesAForeignFolder) {
    test::TempDir dir;
    test::writeText(dir.file("s.yaml"), "objects:\n  - generator: isosurface\n    parameters: {resolution: 16}\n"
                                        "cameras:\n  resolution: [32, 32]\n  grid: {phi: 3, theta: 1}\n");
    const std::string db = dir.file("db.cdb");
    ASSERT_EQ(runDarkroom({"capture", dir.file("s.yaml"), "-o", db}).exitCode, 0);
    test::writeText(db + "/notes.txt", "mine");
    fs::create_directories(db + "/sub");
    test::writeText(db + "/sub/keep.txt", "mine too");
    const auto again = runDarkroom({"capture", dir.file("s.yaml"), "-o", db, "--overwrite"});
    ASSERT_EQ(again.exitCode, 0) << again.err;
    EXPECT_EQ(test::readText(db + "/notes.txt"), "mine");
    EXPECT_EQ(test::readText(db + "/sub/keep.txt"), "mine too");
    EXPECT_EQ(countExr(db), 3u);

    // Not Darkroom's: refused untouched, twice for the same reason, no lock left.
    const std::string foreign = dir.file("foreign");
    fs::create_directories(foreign);
    test::writeText(foreign + "/data.csv", "time,FILE\n0,a.png\n");
    test::writeText(foreign + "/thesis.tex", "precious");
    const auto first = runDarkroom({"capture", dir.file("s.yaml"), "-o", foreign, "--overwrite"});
    EXPECT_EQ(first.exitCode, 2);
    EXPECT_NE(first.err.find("refusing to overwrite " + foreign), std::string::npos) << first.err;
    EXPECT_NE(first.err.find("Darkroom did not create it"), std::string::npos) << first.err;
    EXPECT_FALSE(fs::exists(foreign + "/.lock"));
    const auto second = runDarkroom({"capture", dir.file("s.yaml"), "-o", foreign, "--overwrite"});
    EXPECT_EQ(second.err, first.err);
    EXPECT_EQ(test::readText(foreign + "/thesis.tex"), "precious");
    EXPECT_EQ(test::readText(foreign + "/data.csv"), "time,FILE\n0,a.png\n");
    std::size_t entries = 0;
    for (const auto& f : fs::directory_iterator(foreign)) entries += f.exists();
    EXPECT_EQ(entries, 2u);
}
