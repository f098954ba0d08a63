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
    EXPECT_NE(r.out.find("default \"\"; Preset name"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("default linear"), std::string::npos) << r.out;  // an enum default
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

namespace {

// A database of three entries sharing scalar.exr whose data.csv has an
// irregular row, as tolerant readers meet in the wild.
void writeIrregularDatabase(const ColourMapCase& c, const std::string& name) {
    namespace fs = std::filesystem;
    fs::create_directories(c.dir.file(name));
    fs::copy_file(c.dir.file("scalar.exr"), c.dir.file(name + "/scalar.exr"));
    test::writeText(c.dir.file(name + "/data.csv"), "time,FILE\n0,scalar.exr\n1,scalar.exr,extra\n2,scalar.exr\n");
}

const char* kForeachPipeline = R"(darkroom: 1
nodes:
  read: {type: CinemaReader, parameters: {database: db.cdb}}
  colour: {type: ColorMapping, parameters: {channel: value}}
  write: {type: ImageWriter, parameters: {path: name.png}}
edges:
  - read.image -> colour.image
  - colour.image -> write.image
)";

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

}  // namespace

// Issue 29 item 7: a misspelt node type, type to describe, node or port of
// --set is answered with the nearest name (one spelling check, darkroom/strings.h).
TEST(RunnerCli, DidYouMeanForNodeTypesDescribeAndSet) {
    ColourMapCase c;
    test::writeText(c.dir.file("typo.yaml"), "darkroom: 1\nnodes:\n  x:\n    type: ColorMaping\n");
    const auto v = runDarkroom({"validate", c.dir.file("typo.yaml")});
    EXPECT_EQ(v.exitCode, 2);
    EXPECT_NE(v.err.find("typo.yaml:4:11: error: unknown node type 'ColorMaping' for node 'x' (did you mean "
                         "'ColorMapping'?)"),
              std::string::npos)
        << v.err;
    // `run` loads only the plugins a pipeline names; a type none has brings
    // every plugin in, so the suggestion is the same.
    const auto r = runDarkroom({"run", c.dir.file("typo.yaml")});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("unknown node type 'ColorMaping' for node 'x' (did you mean 'ColorMapping'?)"),
              std::string::npos)
        << r.err;
    const auto d = runDarkroom({"describe", "ColorMaping"});
    EXPECT_EQ(d.exitCode, 2);
    EXPECT_NE(d.err.find("unknown node type 'ColorMaping' (did you mean 'ColorMapping'?)"), std::string::npos) << d.err;
    const auto node = runDarkroom({"run", c.dir.file("p.yaml"), "--set", "colur.colormap=magma"});
    EXPECT_EQ(node.exitCode, 2);
    EXPECT_NE(node.err.find("--set 'colur.colormap=magma': no node named 'colur' in the pipeline (did you mean "
                            "'colour'?)"),
              std::string::npos)
        << node.err;
    const auto port = runDarkroom({"run", c.dir.file("p.yaml"), "--set", "colour.colormp=magma"});
    EXPECT_EQ(port.exitCode, 2);
    EXPECT_NE(port.err.find("node 'colour' (ColorMapping) has no input 'colormp' (did you mean 'colormap'?); inputs "
                            "that take a value: "),
              std::string::npos)
        << port.err;
    // A misspelt preset met while running: bad input, as a missing file is.
    const auto preset = runDarkroom({"run", c.dir.file("p.yaml"), "--set", "colour.colormap=virdis"});
    EXPECT_EQ(preset.exitCode, 2);
    EXPECT_NE(preset.err.find("node 'colour' (ColorMapping): colour map '" + c.dir.file("virdis") +
                              "': no such file, and not a preset name (did you mean 'viridis'?)"),
              std::string::npos)
        << preset.err;
    // Nothing near: no guess.
    const auto far = runDarkroom({"describe", "Frobnicator"});
    EXPECT_EQ(far.err.find("did you mean"), std::string::npos) << far.err;
}

// validate checks what the pipeline names exists, at the node's line:
// colour maps (a preset, with the nearest one suggested, or a file), Path
// inputs, and an entry reader's database; it reads no image.
TEST(RunnerCli, ValidateChecksColourMapsFilesAndDatabases) {
    ColourMapCase c;
    namespace fs = std::filesystem;
    fs::create_directories(c.dir.file("empty.cdb"));
    test::writeText(c.dir.file("v.yaml"), R"(darkroom: 1
nodes:
  read: {type: CinemaReader, parameters: {database: empty.cdb}}
  gone: {type: CinemaReader, parameters: {database: gone.cdb}}
  img: {type: ImageReader, parameters: {path: nothing.exr}}
  preset: {type: ColorMapping, parameters: {channel: value, colormap: Virdis}}
  json: {type: ColorMapping, parameters: {channel: value, colormap: maps/none.json}}
  w1: {type: ImageWriter, parameters: {path: a.png}}
  w2: {type: ImageWriter, parameters: {path: b.png}}
  w3: {type: ImageWriter, parameters: {path: c.png}}
edges:
  - read.image -> preset.image
  - preset.image -> w1.image
  - img.image -> json.image
  - json.image -> w2.image
  - gone.image -> w3.image
)");
    const auto r = runDarkroom({"validate", c.dir.file("v.yaml")});
    EXPECT_EQ(r.exitCode, 2);
    const std::string v = c.dir.file("v.yaml");
    for (const std::string& expected :
         {v + ":3:3: error: node 'read' (CinemaReader): database: '" + c.dir.file("empty.cdb") +
              "' is not a Cinema database: it has no data.csv",
          v + ":4:3: error: node 'gone' (CinemaReader): database: cannot open Cinema database '" +
              c.dir.file("gone.cdb") + "': no such file or directory",
          v + ":5:3: error: node 'img' (ImageReader): path 'nothing.exr': " + c.dir.file("nothing.exr") +
              " does not exist; expected a file or folder to read",
          v + ":6:3: error: node 'preset' (ColorMapping): colormap 'Virdis' is neither a preset (did you mean "
              "'viridis'?) nor a file",
          v + ":7:3: error: node 'json' (ColorMapping): colormap 'maps/none.json' is neither a preset nor a file (" +
              c.dir.file("maps/none.json") + " does not exist); expected one of viridis,"})
        EXPECT_NE(r.err.find(expected), std::string::npos) << expected << "\n" << r.err;
    EXPECT_EQ(count(r.err, "\n"), 5u) << r.err;

    // What the pipeline itself writes may be read by it; a database whose
    // data.csv is irregular passes with the tolerant reader's warning.
    writeIrregularDatabase(c, "db.cdb");
    test::writeText(c.dir.file("ok.yaml"), R"(darkroom: 1
nodes:
  read: {type: CinemaReader, parameters: {database: db.cdb}}
  first: {type: ImageWriter, parameters: {path: made/first.exr}}
  again: {type: ImageReader, parameters: {path: made/first.exr}}
  second: {type: ImageWriter, parameters: {path: second.exr}}
edges:
  - read.image -> first.image
  - again.image -> second.image
)");
    const auto ok = runDarkroom({"validate", c.dir.file("ok.yaml")});
    EXPECT_EQ(ok.exitCode, 0) << ok.err;
    EXPECT_NE(ok.err.find("ok.yaml:3:3: warning: node 'read' (CinemaReader): " + c.dir.file("db.cdb/data.csv") +
                          ":3: row has more cells than the header"),
              std::string::npos)
        << ok.err;
    EXPECT_FALSE(fs::exists(c.dir.file("made"))) << "validate writes nothing";
}

// docs/cli.md: a missing database is bad input (exit 2), whichever command
// meets it, and the message names the node that reads it.
TEST(RunnerCli, MissingDatabaseExits2Everywhere) {
    ColourMapCase c;
    test::writeText(c.dir.file("each.yaml"), kForeachPipeline);
    const auto info = runDarkroom({"info", c.dir.file("db.cdb")});
    EXPECT_EQ(info.exitCode, 2) << info.err;
    EXPECT_NE(info.err.find("cannot open Cinema database '" + c.dir.file("db.cdb") + "'"), std::string::npos)
        << info.err;
    for (const std::vector<std::string>& more : {std::vector<std::string>{}, {"--foreach", "read"}}) {
        std::vector<std::string> args{"-q", "run", c.dir.file("each.yaml"), "-o", c.dir.file("out")};
        args.insert(args.end(), more.begin(), more.end());
        const auto r = runDarkroom(args);
        EXPECT_EQ(r.exitCode, 2) << r.err;
        EXPECT_NE(r.err.find("error: node 'read' (CinemaReader): cannot open Cinema database '" +
                             c.dir.file("db.cdb") + "': no such file or directory"),
                  std::string::npos)
            << r.err;
        EXPECT_EQ(count(r.err, "\n"), 1u) << r.err;
    }
    // A folder without data.csv is no database either.
    std::filesystem::create_directories(c.dir.file("db.cdb"));
    const auto empty = runDarkroom({"-q", "run", c.dir.file("each.yaml"), "-o", c.dir.file("out")});
    EXPECT_EQ(empty.exitCode, 2) << empty.err;
    EXPECT_NE(empty.err.find("it has no data.csv"), std::string::npos) << empty.err;
}

// The tolerant reader's warning about data.csv comes at every entry of
// --foreach: printed once, with the count at the end of the run.
TEST(RunnerCli, ForeachFoldsARepeatedWarningIntoOneLineWithItsCount) {
    ColourMapCase c;
    writeIrregularDatabase(c, "db.cdb");
    test::writeText(c.dir.file("each.yaml"), kForeachPipeline);
    const auto r = runDarkroom({"-q", "run", c.dir.file("each.yaml"), "--foreach", "read", "-o", c.dir.file("out")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(std::filesystem::exists(c.dir.file("out/name_time=2.png")));
    const std::string warning = "node 'read' (CinemaReader): warning: " + c.dir.file("db.cdb/data.csv") +
                                ":3: row has more cells than the header";
    EXPECT_EQ(count(r.err, warning), 2u) << r.err;  // once as it comes, once in the note
    EXPECT_NE(r.err.find("darkroom: note: given 3 times in this run, shown once above: " + warning),
              std::string::npos)
        << r.err;
    EXPECT_EQ(count(r.err, "\n"), 2u) << r.err;
}

// Highway's start-up probe of its timer (apps/darkroom/highway_timer.cpp)
// binds to the runner's own answer, not libhwy's 6 ms spin: the dynamic
// linker's record of its bindings says which object supplied the symbol.
TEST(RunnerCli, HighwaysTimerProbeAtStartIsTheRunnersOwn) {
    const auto r = runDarkroom({"--version"}, {"LD_DEBUG=bindings"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::string binding;
    for (std::size_t at = 0; (at = r.err.find("TimerResolution", at)) != std::string::npos; ++at) {
        const std::size_t begin = r.err.rfind('\n', at) + 1, end = r.err.find('\n', at);
        binding = r.err.substr(begin, end - begin);
        if (binding.find("libhwy") != std::string::npos) break;  // libhwy's own call
    }
    ASSERT_FALSE(binding.empty()) << "libhwy's start-up no longer asks for TimerResolution (harmless: remove "
                                     "highway_timer.cpp)";
    // "binding file .../libhwy.so.1 [0] to .../darkroom [0]: normal symbol `...TimerResolution...'"
    const std::size_t to = binding.find(" to ");
    ASSERT_NE(to, std::string::npos) << binding;
    EXPECT_NE(binding.find("darkroom [0]:", to), std::string::npos) << binding;
    EXPECT_EQ(binding.find("libhwy", to), std::string::npos) << binding;
}
