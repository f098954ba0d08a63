// The runner as a user meets it: exit codes (0 ok, 1 runtime failure, 2 bad
// usage or input) and one clear line per error naming the file or node.
#include "runner_process.h"
#include "test_support.h"

#include <darkroom/data/image_io.h>
#include <darkroom/version.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

using namespace darkroom;
using darkroom::test::runDarkroom;

namespace {

std::string fixturePlugin(const std::string& name) {
    return std::string(DARKROOM_FIXTURE_PLUGIN_DIR) + "/darkroom-fixture-" + name + ".so";
}

// A float EXR with a scalar ramp, and a pipeline colour-mapping it to PNG.
struct ColourMapCase {
    test::TempDir dir;
    ColourMapCase() {
        auto img = test::makeImage(16, 8, {"value"}, [](int x, int, int) { return float(x) / 15.0f; });
        writeImage(*img, dir.file("scalar.exr"));
        test::writeText(dir.file("p.yaml"), R"(darkroom: 1
nodes:
  read:
    type: ImageReader
    parameters:
      path: scalar.exr
  colour:
    type: ColorMapping
    parameters:
      channel: value
  write:
    type: ImageWriter
    parameters:
      path: out.png
edges:
  - read.image -> colour.image
  - colour.image -> write.image
)");
    }
};

}  // namespace

TEST(RunnerCli, PluginsListsTheFirstPlugins) {
    const auto r = runDarkroom({"plugins"});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    for (const char* t : {"ImageReader", "ImageWriter", "ColorMapping"}) EXPECT_NE(r.out.find(t), std::string::npos) << t;
    const auto j = runDarkroom({"plugins", "--json"});
    EXPECT_EQ(j.exitCode, 0);
    EXPECT_EQ(j.out.rfind("{\"plugins\":[", 0), 0u) << j.out.substr(0, 80);
    EXPECT_NE(j.out.find("\"type\":\"ColorMapping\""), std::string::npos);
}

TEST(RunnerCli, WrongAbiPluginIsRefusedAndTheRunnerGoesOn) {
    const auto r = runDarkroom({"--plugin-path", fixturePlugin("wrong-abi"), "plugins"});
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_NE(r.err.find(fixturePlugin("wrong-abi")), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("ABI version " + std::to_string(DARKROOM_ABI_VERSION + 98)), std::string::npos) << r.err;
    EXPECT_NE(r.out.find("ColorMapping"), std::string::npos);
}

TEST(RunnerCli, PluginPathFromTheEnvironment) {
    const auto r = runDarkroom({"describe", "FixtureScale"}, {"DARKROOM_PLUGIN_PATH=" + fixturePlugin("good")});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("factor"), std::string::npos);
}

TEST(RunnerCli, DescribeShowsPortsAndRejectsUnknownTypes) {
    const auto r = runDarkroom({"describe", "ColorMapping"});
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_NE(r.out.find("colormap"), std::string::npos);
    EXPECT_NE(r.out.find("default viridis"), std::string::npos);
    const auto bad = runDarkroom({"describe", "NoSuchType"});
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.err.find("unknown node type 'NoSuchType'"), std::string::npos) << bad.err;
    // A writer is an output of the pipeline though it has an output port.
    const auto writer = runDarkroom({"describe", "CinemaWriter"});
    EXPECT_NE(writer.out.find("database       outpath"), std::string::npos) << writer.out;
    EXPECT_NE(writer.out.find("(this node writes files: it is an output of the pipeline)"), std::string::npos)
        << writer.out;
}

TEST(RunnerCli, RunColourMapsAFloatExrIntoAPng) {
    ColourMapCase c;
    const auto r = runDarkroom({"run", c.dir.file("p.yaml")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(r.err.empty()) << "quiet when stderr is not a terminal: " << r.err;
    const auto png = readImage(c.dir.file("out.png"));
    EXPECT_EQ(png->width(), 16);
    EXPECT_TRUE(png->hasChannel("R") && png->hasChannel("A"));
    // viridis runs from dark purple to yellow: red grows along the ramp.
    EXPECT_LT(png->hostFloat("R")[0], png->hostFloat("R")[15]);
}

TEST(RunnerCli, OutputDirectoryAndSetOverride) {
    ColourMapCase c;
    const std::string out = c.dir.file("results");
    const auto r = runDarkroom({"run", c.dir.file("p.yaml"), "--output", out, "--set", "write.path=other.png",
                                "--set", "colour.colormap=magma"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NO_THROW(readImage(out + "/other.png"));
}

TEST(RunnerCli, MalformedYamlGivesLineColumnAndExit2) {
    test::TempDir dir;
    test::writeText(dir.file("bad.yaml"), "darkroom: 1\nnodes:\n  a: {type: ImageReader\n");
    for (const char* cmd : {"validate", "run"}) {
        const auto r = runDarkroom({cmd, dir.file("bad.yaml")});
        EXPECT_EQ(r.exitCode, 2) << cmd;
        EXPECT_NE(r.err.find(dir.file("bad.yaml") + ":"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("malformed YAML"), std::string::npos) << r.err;
    }
}

TEST(RunnerCli, BadInputsExit2) {
    ColourMapCase c;
    EXPECT_EQ(runDarkroom({"run", c.dir.file("missing.yaml")}).exitCode, 2);
    const auto set = runDarkroom({"run", c.dir.file("p.yaml"), "--set", "colour.range=sideways"});
    EXPECT_EQ(set.exitCode, 2);
    EXPECT_NE(set.err.find("not one of"), std::string::npos) << set.err;
    EXPECT_EQ(runDarkroom({"run", c.dir.file("p.yaml"), "--set", "nodot"}).exitCode, 2);
    EXPECT_EQ(runDarkroom({"frobnicate"}).exitCode, 2);
    test::writeText(c.dir.file("unknown.yaml"), "darkroom: 1\nnodes:\n  x:\n    type: Mystery\n");
    const auto v = runDarkroom({"validate", c.dir.file("unknown.yaml")});
    EXPECT_EQ(v.exitCode, 2);
    EXPECT_NE(v.err.find(":4:11: error: unknown node type 'Mystery'"), std::string::npos) << v.err;
}

// A missing input file is bad input, found while running: exit 2 as for a
// bad pipeline (issue 18), naming the node and the file.
TEST(RunnerCli, MissingInputFileExit2NamesTheNode) {
    ColourMapCase c;
    const auto r = runDarkroom({"run", c.dir.file("p.yaml"), "--set", "read.path=nothing-here.exr"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("node 'read' (ImageReader)"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("nothing-here.exr"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line per error: " << r.err;
}

TEST(RunnerCli, ValidateReportsOk) {
    ColourMapCase c;
    const auto r = runDarkroom({"validate", c.dir.file("p.yaml")});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("OK (3 nodes, 2 edges, outputs: write)"), std::string::npos) << r.out;
}

// L4 (issue 26): "Permission denied" exits as every other failure of its
// kind: a file the runner must read is bad input (2), wherever it is read; a
// file it cannot write is a runtime failure (1). Run without root's power
// to read anything (as nobody under setpriv when the test runs as root).
TEST(RunnerCli, PermissionDeniedExitsByWhetherReadingOrWriting) {
    if (const std::string why = test::whyUnprivilegedCannotRun(); !why.empty()) GTEST_SKIP() << why;
    ColourMapCase c;
    namespace fs = std::filesystem;
    fs::permissions(c.dir.path(), fs::perms::all);
    const auto run = [&](const std::vector<std::string>& more) {
        std::vector<std::string> args{"-q", "run", c.dir.file("p.yaml"), "--output", c.dir.file("out")};
        args.insert(args.end(), more.begin(), more.end());
        return test::runDarkroomUnprivileged(args);
    };
    fs::create_directories(c.dir.file("out"));
    fs::permissions(c.dir.file("out"), fs::perms::all);
    const auto ok = run({});
    ASSERT_EQ(ok.exitCode, 0) << ok.err;

    fs::permissions(c.dir.file("scalar.exr"), fs::perms::none);
    const auto image = run({});
    EXPECT_EQ(image.exitCode, 2) << image.err;
    EXPECT_NE(image.err.find("node 'read' (ImageReader)"), std::string::npos) << image.err;
    EXPECT_NE(image.err.find("Permission denied"), std::string::npos) << image.err;
    fs::permissions(c.dir.file("scalar.exr"), fs::perms::owner_read | fs::perms::others_read);

    fs::permissions(c.dir.file("p.yaml"), fs::perms::none);
    const auto pipeline = run({});
    EXPECT_EQ(pipeline.exitCode, 2) << pipeline.err;
    EXPECT_NE(pipeline.err.find("Permission denied"), std::string::npos) << pipeline.err;
    fs::permissions(c.dir.file("p.yaml"), fs::perms::owner_read | fs::perms::others_read);

    fs::permissions(c.dir.file("out"), fs::perms::owner_all | fs::perms::others_read | fs::perms::others_exec);
    const auto write = run({});
    EXPECT_EQ(write.exitCode, 1) << write.err;
    EXPECT_NE(write.err.find("node 'write' (ImageWriter)"), std::string::npos) << write.err;
    EXPECT_NE(write.err.find("Permission denied"), std::string::npos) << write.err;
}

// D3 (issue 26): entries whose values differ only in characters a file name
// cannot keep (a/b, a~b) would share one output file: the run is refused
// before anything is written, naming both entries.
TEST(RunnerCli, ForeachRefusesEntriesThatWouldShareAnOutputFile) {
    ColourMapCase c;
    namespace fs = std::filesystem;
    fs::create_directories(c.dir.file("db.cdb"));
    fs::copy_file(c.dir.file("scalar.exr"), c.dir.file("db.cdb/scalar.exr"));
    test::writeText(c.dir.file("db.cdb/data.csv"), "label,FILE\nplain,scalar.exr\na/b,scalar.exr\na~b,scalar.exr\n");
    test::writeText(c.dir.file("each.yaml"), R"(darkroom: 1
nodes:
  read: {type: CinemaReader, parameters: {database: db.cdb}}
  colour: {type: ColorMapping, parameters: {channel: value}}
  write: {type: ImageWriter, parameters: {path: name.png}}
edges:
  - read.image -> colour.image
  - colour.image -> write.image
)");
    const auto r = runDarkroom({"-q", "run", c.dir.file("each.yaml"), "--foreach", "read", "--output",
                                c.dir.file("out"), "--index", c.dir.file("out/index.csv")});
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("label=\"a/b\" and label=\"a~b\" would both be written to"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(c.dir.file("out/name_label=plain.png")));
    EXPECT_FALSE(fs::exists(c.dir.file("out/index.csv")));
    const auto one = runDarkroom({"-q", "run", c.dir.file("each.yaml"), "--foreach", "read", "--where",
                                  "label <> 'a~b'", "--output", c.dir.file("out")});
    EXPECT_EQ(one.exitCode, 0) << one.err;
    EXPECT_TRUE(fs::exists(c.dir.file("out/name_label=a~b.png")));
}
