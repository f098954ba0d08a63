// Shading databases that store no camera, as a user runs it: SSAO over
// every picture of TTK's composable image set with --foreach, without a
// Camera node: one entry per picture (not per channel row), named by the
// object, and ONE warning for the run saying what was assumed. A database
// without depth is named in the error.
#include "runner_process.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

using namespace darkroom;
using darkroom::test::runDarkroom;

namespace {

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
    return n;
}

std::string ssaoPipeline(const std::string& db) {
    return R"(darkroom: 1
nodes:
  read:
    type: CinemaReader
    parameters:
      database: )" + db + R"(
  ao:
    type: SSAO
    parameters:
      radius: 0.04
      resolution: half
  write:
    type: ImageWriter
    parameters:
      path: ao.png
      channels: AO
edges:
  - read.image -> ao.image
  - ao.image -> write.image
)";
}

}  // namespace

TEST(NoCameraCli, ForeachOverTtkDatabaseShadesEachPictureOnceWithOneWarning) {
    const std::string db = test::sharedData("cinema/ttk_extracts_001.cdb");
    if (db.empty()) GTEST_SKIP() << "../shared/data/cinema/ttk_extracts_001.cdb is absent";
    test::TempDir dir;
    test::writeText(dir.file("p.yaml"), ssaoPipeline(db));
    const auto r = runDarkroom({"-q", "run", dir.file("p.yaml"), "--foreach", "read", "-o", dir.file("out")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    // Six channel rows, two pictures (objects 000 and 012).
    std::vector<std::string> written;
    for (const auto& e : std::filesystem::directory_iterator(dir.file("out"))) written.push_back(e.path().filename());
    std::sort(written.begin(), written.end());
    EXPECT_EQ(written, (std::vector<std::string>{"ao_object=000.png", "ao_object=012.png"}));
    EXPECT_EQ(count(r.err, "warning:"), 1u) << r.err;
    EXPECT_EQ(count(r.err, "node 'ao' (SSAO): warning: the image carries no camera"), 1u) << r.err;
    EXPECT_EQ(count(r.err, "note:"), 0u) << r.err;  // said once, not folded from repeats
}

TEST(NoCameraCli, ADatabaseWithoutDepthIsNamed) {
    const std::string db = test::sharedData("cinema/sphere.cdb");
    if (db.empty()) GTEST_SKIP() << "../shared/data/cinema/sphere.cdb is absent";
    test::TempDir dir;
    test::writeText(dir.file("p.yaml"), ssaoPipeline(db));
    const auto r = runDarkroom({"-q", "run", dir.file("p.yaml"), "-o", dir.file("out")});
    EXPECT_NE(r.exitCode, 0);
    // The database as the reader resolved it (an absolute path).
    EXPECT_NE(r.err.find("sphere.cdb stores no depth (channels: R, G, B)"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("database /"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("channel 'Z'"), std::string::npos) << r.err;
}
