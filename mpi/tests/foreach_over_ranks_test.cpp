// `mpirun -np N darkroom run PIPELINE --foreach NODE` shades the same
// images, byte for byte, and writes the same index as one process; a run
// that failed part-way resumes; rank 0 alone draws the progress bar.
#include "run_process.h"
#include "small_database.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <regex>

namespace darkroom::test {
namespace {

// Two outputs per entry, so the index has two file columns.
const char* kPipeline =
    "darkroom: 1\n"
    "nodes:\n"
    "  read:\n"
    "    type: CinemaReader\n"
    "    parameters: {database: db.cdb}\n"
    "  colour:\n"
    "    type: ColorMapping\n"
    "    parameters: {channel: height, colormap: viridis}\n"
    "  ao:\n"
    "    type: SSAO\n"
    "    parameters: {radius: 0.1}\n"
    "  png:\n"
    "    type: ImageWriter\n"
    "    parameters: {path: shaded/view.png}\n"
    "  exr:\n"
    "    type: ImageWriter\n"
    "    parameters: {path: 'exr/{entry}.exr'}\n"
    "edges:\n"
    "  - read.image -> colour.image\n"
    "  - colour.image -> ao.image\n"
    "  - ao.image -> png.image\n"
    "  - ao.image -> exr.image\n";

struct Batch {
    TempDir dir;
    std::string pipeline = dir.file("shade.yaml");
    Batch() {
        writeText(pipeline, kPipeline);
        const RunResult r = captureSmallDatabase(dir);
        EXPECT_EQ(r.exitCode, 0) << r.err;
    }
    std::vector<std::string> shade(const std::string& out) const {
        return {"run", pipeline, "--foreach", "read", "-o", dir.file(out), "--index", dir.file(out + "/index.csv"), "-q"};
    }
};

void expectSameAsOneProcess(int ranks) {
    Batch b;
    const RunResult one = runAlone(b.shade("one"));
    ASSERT_EQ(one.exitCode, 0) << one.err;
    const RunResult many = runOnRanks(ranks, b.shade("many"));
    ASSERT_EQ(many.exitCode, 0) << many.err << many.out;
    for (const char* folder : {"", "/shaded", "/exr"})
        EXPECT_EQ(compareFolders(b.dir.file(std::string("one") + folder), b.dir.file(std::string("many") + folder)), "")
            << folder;
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(b.dir.file("one/shaded")), {}), 10);
    const std::string index = readText(b.dir.file("many/index.csv"));
    EXPECT_EQ(index.substr(0, index.find('\n')), "phi,theta,FILE_png,FILE_exr");
    EXPECT_NE(index.find("\n-180,0,shaded/view_phi=-180_theta=0.png,exr/phi=-180_theta=0.exr\n"), std::string::npos)
        << index;
}

TEST(ForeachOverRanks, FourRanksShadeWhatOneProcessShadesByteForByte) { expectSameAsOneProcess(4); }
TEST(ForeachOverRanks, ThreeRanksToo) { expectSameAsOneProcess(3); }

TEST(ForeachOverRanks, ARunThatFailedPartWayResumesAndCompletes) {
    Batch b;
    ASSERT_EQ(runAlone(b.shade("reference")).exitCode, 0);
    // A broken product makes its entry fail; the ranks stop taking entries.
    const std::string product = b.dir.file("db.cdb/phi=-36_theta=0.exr");
    const std::string bytes = readText(product);
    writeText(product, bytes.substr(0, 100));
    const RunResult failed = runOnRanks(4, b.shade("out"));
    EXPECT_EQ(failed.exitCode, 1) << failed.err;
    EXPECT_NE(failed.err.find("entry phi=-36_theta=0"), std::string::npos) << failed.err;
    EXPECT_FALSE(std::filesystem::exists(b.dir.file("out/shaded/view_phi=-36_theta=0.png")));
    // The index lists what was done, so a script can see how far it got.
    const std::string partial = readText(b.dir.file("out/index.csv"));
    EXPECT_EQ(partial.find("phi=-36_theta=0"), std::string::npos);

    writeText(product, bytes);
    std::vector<std::string> args = b.shade("out");
    args.back() = "--resume";  // instead of -q: the summary says what was kept
    const RunResult resumed = runOnRanks(4, args);
    ASSERT_EQ(resumed.exitCode, 0) << resumed.err;
    const std::smatch m = [&] {
        std::smatch x;
        std::regex_search(resumed.err, x, std::regex("shaded (\\d+) entries over 4 ranks \\(per rank: [0-9, ]+\\), (\\d+) kept by --resume"));
        return x;
    }();
    ASSERT_EQ(m.size(), 3u) << resumed.err;
    EXPECT_EQ(std::stoi(m[1]) + std::stoi(m[2]), 10);
    EXPECT_GE(std::stoi(m[1]), 1);
    for (const char* folder : {"", "/shaded", "/exr"})
        EXPECT_EQ(compareFolders(b.dir.file(std::string("reference") + folder), b.dir.file(std::string("out") + folder)), "")
            << folder;
}

TEST(ForeachOverRanks, OnlyRankZeroDrawsTheProgressBar) {
    Batch b;
    std::vector<std::string> args = b.shade("out");
    args.back() = "--progress";
    // --tag-output prefixes what each rank writes with [job,rank].
    std::vector<std::string> argv{DARKROOM_MPIEXEC, "--tag-output", "-np", "4", "--oversubscribe", DARKROOM_RUNNER};
    argv.insert(argv.end(), args.begin(), args.end());
    const RunResult r = runProgram(argv, {"OMPI_ALLOW_RUN_AS_ROOT=1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::regex bar("\\[\\d+,(\\d+)\\]<stderr>:\r\033\\[Krun \\[");
    int bars = 0;
    for (auto it = std::sregex_iterator(r.out.begin(), r.out.end(), bar); it != std::sregex_iterator(); ++it) {
        EXPECT_EQ((*it)[1].str(), "0");
        ++bars;
    }
    for (auto it = std::sregex_iterator(r.err.begin(), r.err.end(), bar); it != std::sregex_iterator(); ++it) {
        EXPECT_EQ((*it)[1].str(), "0");
        ++bars;
    }
    EXPECT_GE(bars, 1) << r.err;
}

}  // namespace
}  // namespace darkroom::test
