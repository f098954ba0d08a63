// A CinemaWriter under `mpirun -np N darkroom run PIPELINE --foreach NODE`:
// each rank stages its entries, rank 0 merges them into the one database a
// single process writes (data.csv and every product byte for byte), before
// the sinks that run after the last entry (a Movie of that database); a run
// that failed part-way, or was killed with entries staged, is completed by a
// resume; a database the node's mode refuses stops the run once, before any
// shading.
#include "run_process.h"
#include "small_database.h"
#include "test_support.h"

#include <darkroom/data/cinema/database.h>
#include <darkroom/data/cinema/writer.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <regex>

namespace darkroom::test {
namespace {

namespace fs = std::filesystem;

// Two databases (pictures and G-buffers with the colour added) and a movie of
// the pictures, which runs after the last entry.
const char* kWriters =
    "darkroom: 1\n"
    "nodes:\n"
    "  read:\n"
    "    type: CinemaReader\n"
    "    parameters: {database: db.cdb}\n"
    "  colour:\n"
    "    type: ColorMapping\n"
    "    parameters: {channel: height, colormap: viridis}\n"
    "  pictures:\n"
    "    type: CinemaWriter\n"
    "    parameters: {database: shaded.cdb}\n"
    "  buffers:\n"
    "    type: CinemaWriter\n"
    "    parameters: {database: buffers.cdb, format: exr}\n"
    "edges:\n"
    "  - read.image -> colour.image\n"
    "  - colour.image -> pictures.image\n"
    "  - read.row -> pictures.row\n"
    "  - colour.image -> buffers.image\n"
    "  - read.row -> buffers.row\n";

const char* kMovie =
    "  movie:\n"
    "    type: Movie\n"
    "    parameters: {where: \"theta=0\", orderBy: phi, path: orbit.mp4, frameRate: 4}\n";

// The movie reads the pictures' database through the writer's `written`
// output: after the merge, the batch gives it the merged database.
std::string withMovie() {
    std::string p = kWriters;
    p.insert(p.find("edges:"), kMovie);
    return p + "  - pictures.written -> movie.database\n";
}

int count(const std::string& text, const std::string& what) {
    int n = 0;
    for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
    return n;
}

struct Batch {
    TempDir dir;
    explicit Batch(const std::string& pipeline = withMovie()) {
        writeText(dir.file("shade.yaml"), pipeline);
        const RunResult r = captureSmallDatabase(dir);
        EXPECT_EQ(r.exitCode, 0) << r.err;
    }
    std::vector<std::string> shade(const std::string& out, std::vector<std::string> more = {}) const {
        std::vector<std::string> args{"run", dir.file("shade.yaml"), "--foreach", "read", "-o", dir.file(out)};
        args.insert(args.end(), more.begin(), more.end());
        return args;
    }
    // Every file of the output folder and of both databases, and no staging left.
    void expectSame(const std::string& a, const std::string& b) const {
        for (const char* folder : {"", "/shaded.cdb", "/buffers.cdb"})
            EXPECT_EQ(compareFolders(dir.file(a + folder), dir.file(b + folder)), "") << b << folder;
    }
};

void expectSameAsOneProcess(int ranks) {
    Batch b;
    const RunResult one = runAlone(b.shade("one", {"-q"}));
    ASSERT_EQ(one.exitCode, 0) << one.err;
    const RunResult many = runOnRanks(ranks, b.shade("many", {"-q"}));
    ASSERT_EQ(many.exitCode, 0) << many.err << many.out;
    b.expectSame("one", "many");
    // The movie was made from the merged database: all five theta=0 entries.
    EXPECT_TRUE(fs::is_regular_file(b.dir.file("many/orbit.mp4")));
    EXPECT_EQ(CinemaDatabase::open(b.dir.file("many/shaded.cdb")).rowCount(), 10u);
    EXPECT_EQ(std::distance(fs::directory_iterator(b.dir.file("many/buffers.cdb")), {}), 12);  // + data.csv and the marker
    const RunResult info = runAlone({"info", b.dir.file("many/shaded.cdb")});
    EXPECT_EQ(info.exitCode, 0) << info.err;
    EXPECT_NE(info.out.find("10 rows"), std::string::npos) << info.out;
}

TEST(CinemaWriterOverRanks, FourRanksWriteTheDatabaseOneProcessWrites) { expectSameAsOneProcess(4); }
TEST(CinemaWriterOverRanks, ThreeRanksToo) { expectSameAsOneProcess(3); }

TEST(CinemaWriterOverRanks, ARunThatFailedPartWayResumesAndCompletes) {
    Batch b;
    ASSERT_EQ(runAlone(b.shade("reference", {"-q"})).exitCode, 0);
    // A broken product makes its entry fail; the ranks stop taking entries.
    const std::string product = b.dir.file("db.cdb/phi=-36_theta=0.exr");
    const std::string bytes = readText(product);
    writeText(product, bytes.substr(0, 100));
    const RunResult failed = runOnRanks(4, b.shade("out", {"-q"}));
    EXPECT_EQ(failed.exitCode, 1) << failed.err;
    EXPECT_EQ(count(failed.err, "entry phi=-36_theta=0"), 1) << failed.err;
    // What was shaded is merged: a valid database without the failed entry,
    // no staging left, and no movie (nothing runs after a failed entry).
    const auto partial = CinemaDatabase::open(b.dir.file("out/shaded.cdb"));
    EXPECT_GE(partial.rowCount(), 1u);
    EXPECT_LT(partial.rowCount(), 10u);
    EXPECT_EQ(std::distance(fs::directory_iterator(b.dir.file("out/shaded.cdb")), {}), long(partial.rowCount()) + 2);  // + data.csv and the marker
    EXPECT_EQ(readText(b.dir.file("out/shaded.cdb/data.csv")).find("phi=-36_theta=0"), std::string::npos);
    EXPECT_FALSE(fs::exists(b.dir.file("out/shaded.cdb.staging")));
    EXPECT_FALSE(fs::exists(b.dir.file("out/orbit.mp4")));

    writeText(product, bytes);
    const RunResult resumed = runOnRanks(
        4, b.shade("out", {"--resume", "--set", "pictures.mode=resume", "--set", "buffers.mode=resume"}));
    ASSERT_EQ(resumed.exitCode, 0) << resumed.err;
    std::smatch m;
    ASSERT_TRUE(std::regex_search(resumed.err, m,
                                  std::regex("shaded (\\d+) entries over 4 ranks \\(per rank: [0-9, ]+\\), (\\d+) "
                                             "kept by --resume")))
        << resumed.err;
    // Entries both databases have are not shaded again.
    EXPECT_EQ(std::size_t(std::stoi(m[2])), partial.rowCount());
    EXPECT_EQ(std::stoi(m[1]) + std::stoi(m[2]), 10);
    b.expectSame("reference", "out");
}

TEST(CinemaWriterOverRanks, AKilledRunsStagedEntriesAreRefusedByCreateAndAdoptedByResume) {
    Batch b(kWriters);
    ASSERT_EQ(runAlone(b.shade("reference", {"-q"})).exitCode, 0);
    // What a killed run over ranks leaves: staging databases, the database not
    // yet written. One rank's worth, written by the runner alone.
    fs::create_directories(b.dir.file("out"));
    const RunResult stage = runAlone(b.shade(
        "out", {"-q", "--where", "theta=40", "--set", "pictures.database=" + b.dir.file("out/shaded.cdb.staging/rank-5"),
                "--set", "buffers.database=" + b.dir.file("out/buffers.cdb.staging/rank-5")}));
    ASSERT_EQ(stage.exitCode, 0) << stage.err;
    // The marker with which a run over ranks claims its staging folders.
    for (const char* folder : {"out/shaded.cdb.staging", "out/buffers.cdb.staging"})
        writeText(b.dir.file(std::string(folder) + "/.darkroom-staging"), "");

    const RunResult refused = runOnRanks(3, b.shade("out"));
    EXPECT_EQ(refused.exitCode, 2) << refused.err;
    EXPECT_EQ(count(refused.err, "left 5 entries staged in " + b.dir.file("out/shaded.cdb.staging")), 1)
        << refused.err;
    EXPECT_EQ(refused.err.find("entries over 3 ranks"), std::string::npos) << refused.err;  // nothing shaded
    EXPECT_FALSE(fs::exists(b.dir.file("out/shaded.cdb")));

    {  // A staging database another run is writing is not taken.
        CinemaWriter other(b.dir.file("out/shaded.cdb.staging/rank-0"), {"phi", "theta"});
        const RunResult busy = runOnRanks(3, b.shade("out", {"--set", "pictures.mode=resume"}));
        EXPECT_EQ(busy.exitCode, 2) << busy.err;
        EXPECT_EQ(count(busy.err, "rank-0 is being written by another process"), 1) << busy.err;
        EXPECT_FALSE(fs::exists(b.dir.file("out/shaded.cdb")));
        other.finish();
        fs::remove_all(b.dir.file("out/shaded.cdb.staging/rank-0"));
    }

    const RunResult resumed = runOnRanks(
        3, b.shade("out", {"--resume", "--set", "pictures.mode=resume", "--set", "buffers.mode=resume"}));
    ASSERT_EQ(resumed.exitCode, 0) << resumed.err;
    EXPECT_NE(resumed.err.find("shaded 5 entries over 3 ranks"), std::string::npos) << resumed.err;
    EXPECT_NE(resumed.err.find("5 kept by --resume"), std::string::npos) << resumed.err;
    b.expectSame("reference", "out");
}

TEST(CinemaWriterOverRanks, CreateOntoAnExistingDatabaseFailsOnceBeforeShading) {
    Batch b;
    ASSERT_EQ(runAlone(b.shade("out", {"-q"})).exitCode, 0);
    const std::string before = readText(b.dir.file("out/shaded.cdb/data.csv"));
    const RunResult again = runOnRanks(4, b.shade("out"));
    EXPECT_EQ(again.exitCode, 2) << again.err;
    EXPECT_EQ(count(again.err, "error:"), 1) << again.err;
    EXPECT_NE(again.err.find("node 'pictures' (CinemaWriter): database " + b.dir.file("out/shaded.cdb") +
                             " already exists and is not empty"),
              std::string::npos)
        << again.err;
    EXPECT_EQ(again.err.find("entries over 4 ranks"), std::string::npos) << again.err;
    EXPECT_EQ(readText(b.dir.file("out/shaded.cdb/data.csv")), before);
    EXPECT_FALSE(fs::exists(b.dir.file("out/shaded.cdb.staging")));
}

}  // namespace
}  // namespace darkroom::test
