// Limits a user sets on the runner (--max-*) and bad input found while a
// pipeline runs or a scene is captured: exit 2 with one line naming the node
// or file:line, never a signal (issue 18).
#include "runner_process.h"
#include "test_support.h"

#include <darkroom/data/image_io.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

using namespace darkroom;
using darkroom::test::runDarkroom;

namespace {

// One line on stderr containing every piece; exit 2, not a signal.
void expectBadInput(const test::ProcessResult& r, std::initializer_list<const char*> pieces) {
    EXPECT_EQ(r.exitCode, 2) << r.err;
    for (const char* p : pieces) EXPECT_NE(r.err.find(p), std::string::npos) << "'" << p << "' not in: " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

// A 64 x 64 scalar EXR read, colour-mapped (new R, G, B planes: 48 KiB) and written.
struct Pipeline {
    test::TempDir dir;
    explicit Pipeline(const std::string& middle = "colour:\n    type: ColorMapping\n    parameters:\n      channel: value\n") {
        auto img = test::makeImage(64, 64, {"value"}, [](int x, int, int) { return float(x) / 63.0f; });
        writeImage(*img, dir.file("scalar.exr"));
        test::writeText(dir.file("p.yaml"), "darkroom: 1\nnodes:\n  read:\n    type: ImageReader\n    parameters:\n"
                                            "      path: scalar.exr\n  " + middle +
                                            "  write:\n    type: ImageWriter\n    parameters:\n      path: out.exr\n"
                                            "edges:\n  - read.image -> colour.image\n  - colour.image -> write.image\n");
    }
    std::string path() const { return dir.file("p.yaml"); }
};

}  // namespace

TEST(LimitsCli, NodeMemoryLimitNamesTheNodeAndTheLimit) {
    Pipeline p;
    expectBadInput(runDarkroom({"run", p.path(), "--max-node-memory", "32K", "-q"}),
                   {"node 'colour'", "--max-node-memory 32 KiB"});
    EXPECT_EQ(runDarkroom({"run", p.path(), "--max-node-memory", "1G", "-q"}).exitCode, 0);
}

TEST(LimitsCli, NodeTimeLimitStopsASlowNodeNamingIt) {
    Pipeline p("colour:\n    type: FixtureSpin\n    parameters:\n      seconds: 60\n");
    const std::string plugin = std::string(DARKROOM_FIXTURE_PLUGIN_DIR) + "/darkroom-fixture-slow.so";
    expectBadInput(runDarkroom({"run", p.path(), "--plugin-path", plugin, "--max-node-seconds", "0.2", "-q"}),
                   {"node 'colour'", "ran past --max-node-seconds 0.2"});
}

TEST(LimitsCli, ImagePixelLimitAppliesToWhatANodeAllocates) {
    Pipeline p;
    const auto r = runDarkroom({"run", p.path(), "--max-image-pixels", "1000", "-q"});
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("--max-image-pixels"), std::string::npos) << r.err;
}

TEST(LimitsCli, BadLimitValuesAreUsageErrors) {
    Pipeline p;
    for (const char* bad : {"4Q", "lots", "-1G"}) {
        const auto r = runDarkroom({"run", p.path(), "--max-node-memory", bad});
        EXPECT_EQ(r.exitCode, 2) << bad;
        EXPECT_NE(r.err.find("--max-node-memory"), std::string::npos) << r.err;
    }
    EXPECT_EQ(runDarkroom({"run", p.path(), "--max-node-seconds", "-3"}).exitCode, 2);
}

TEST(LimitsCli, InputProblemsFoundWhileRunningExitTwo) {
    Pipeline p;
    std::filesystem::remove(p.dir.file("scalar.exr"));
    expectBadInput(runDarkroom({"run", p.path(), "-q"}), {"node 'read'", "scalar.exr"});
}

TEST(LimitsCli, NanParameterIsRefusedByRunAndValidate) {
    Pipeline p("colour:\n    type: Resize\n    parameters:\n      scale: .nan\n");
    for (const char* cmd : {"validate", "run"}) expectBadInput(runDarkroom({cmd, p.path(), "-q"}), {"p.yaml:", "scale"});
}

TEST(LimitsCli, PipelineYamlProblemsExitTwoNamingTheLine) {
    Pipeline p;
    test::writeText(p.path(), "darkroom: 1\nnodes:\n  read:\n    type: ImageReader\n    paramters: {path: x.exr}\n"
                              "edges: []\n");
    expectBadInput(runDarkroom({"validate", p.path()}), {"p.yaml:5:", "did you mean 'parameters'"});
    test::writeText(p.path(), "darkroom: 1\nnodes: &n {read: {type: ImageReader, ui: *n}}\nedges: []\n");
    expectBadInput(runDarkroom({"run", p.path()}), {"p.yaml:2:", "recursive alias"});
}

TEST(LimitsCli, CaptureRefusesExtremeCamerasWithoutASignal) {
    test::TempDir dir;
    const std::string objects = "objects:\n  - generator: isosurface\n    parameters: {resolution: 8}\n";
    const std::pair<const char*, const char*> cases[] = {
        {"cameras:\n  grid: {distance: 1e20}\n", "s.yaml:5:"},
        {"cameras:\n  fov: 1e-300\n", "s.yaml:5:"},
        {"cameras:\n  grid: {target: [1e300, 0, 0]}\n", "s.yaml:5:"},
        {"cameras:\n  projection: orthographic\n  height: 1e300\n", "s.yaml:6:"},
    };
    for (const auto& [cameras, where] : cases) {
        test::writeText(dir.file("s.yaml"), objects + cameras);
        expectBadInput(runDarkroom({"capture", dir.file("s.yaml"), "-o", dir.file("db.cdb")}), {where});
        EXPECT_FALSE(std::filesystem::exists(dir.file("db.cdb"))) << "nothing written, no lock left: " << cameras;
    }
}
