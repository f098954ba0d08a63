// CinemaWriter through `darkroom run --foreach` in one process: the database
// is checked against the node's mode before any entry is shaded, and
// `--resume` with mode resume does not shade again the entries the database
// already holds (runs over MPI ranks: mpi/tests/cinema_writer_over_ranks_test.cpp).
#include "../../../tests/integration/runner/runner_process.h"
#include "test_support.h"
#include "time_series_database.h"

#include <darkroom/data/cinema/database.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <map>

using namespace darkroom;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

namespace {

const char* kPipeline = R"(darkroom: 1
nodes:
  read:
    type: CinemaReader
    parameters: {database: source.cdb}
  write:
    type: CinemaWriter
    parameters: {database: shaded.cdb, format: exr}
edges:
  - read.image -> write.image
  - read.row -> write.row
)";

struct Shading {
    test::TempDir dir;
    Shading() {
        test::writeTimeSeriesDatabase(dir.file("source.cdb"), {1.0, 2.0, 3.0});
        test::writeText(dir.file("shade.yaml"), kPipeline);
    }
    test::ProcessResult shade(std::vector<std::string> more = {}) const {
        std::vector<std::string> args{"-q", "run", dir.file("shade.yaml"), "--foreach", "read", "-o", dir.file("out")};
        args.insert(args.end(), more.begin(), more.end());
        return test::runDarkroom(args);
    }
};

}  // namespace

TEST(CinemaWriterRun, ACreateRunOntoAnExistingDatabaseIsRefusedBeforeShading) {
    Shading r;
    ASSERT_EQ(r.shade().exitCode, 0);
    // An entry that would fail if it were shaded: the refusal comes first.
    test::writeText(r.dir.file("source.cdb/time=1.exr"), "broken");
    const auto again = r.shade();
    EXPECT_EQ(again.exitCode, 2) << again.err;
    EXPECT_THAT(again.err, HasSubstr("node 'write' (CinemaWriter): database " + r.dir.file("out/shaded.cdb") +
                                     " already exists and is not empty"));
    EXPECT_THAT(again.err, ::testing::Not(HasSubstr("time=1.exr")));
}

TEST(CinemaWriterRun, ResumeShadesOnlyWhatTheDatabaseLacks) {
    Shading r;
    ASSERT_EQ(r.shade().exitCode, 0);
    const std::string full = test::readText(r.dir.file("out/shaded.cdb/data.csv"));
    fs::remove(r.dir.file("out/shaded.cdb/time=3.exr"));
    // The entries the database keeps are not read again: a broken source
    // product of one of them does not matter.
    test::writeText(r.dir.file("source.cdb/time=1.exr"), "broken");
    const auto resumed = r.shade({"--resume", "--set", "write.mode=resume"});
    EXPECT_EQ(resumed.exitCode, 0) << resumed.err;
    EXPECT_EQ(test::readText(r.dir.file("out/shaded.cdb/data.csv")), full);
    EXPECT_TRUE(fs::is_regular_file(r.dir.file("out/shaded.cdb/time=3.exr")));
    // Without --resume every entry is shaded (and the broken one fails);
    // with --resume but mode create nothing counts as done.
    fs::remove(r.dir.file("out/shaded.cdb/time=3.exr"));
    EXPECT_EQ(r.shade({"--set", "write.mode=resume"}).exitCode, 1);
    EXPECT_EQ(r.shade({"--resume", "--set", "write.mode=overwrite"}).exitCode, 1);
}

// The node records its settings in the database it writes: a resume with
// others is refused, naming what changed, and leaves no lock behind.
TEST(CinemaWriterRun, ResumeWithOtherSettingsIsRefusedNamingThem) {
    Shading r;
    ASSERT_EQ(r.shade().exitCode, 0);
    const std::string db = r.dir.file("out/shaded.cdb");
    fs::remove(db + "/time=3.exr");
    const auto piz = r.shade({"--resume", "--set", "write.mode=resume", "--set", "write.compression=piz"});
    EXPECT_NE(piz.exitCode, 0);
    EXPECT_THAT(piz.err, HasSubstr("cannot resume " + db +
                                   ": the CinemaWriter settings changed since the capture began (compression zip "
                                   "\u2192 piz)"));
    EXPECT_FALSE(fs::exists(db + "/.lock"));
    EXPECT_FALSE(fs::exists(db + "/time=3.exr"));
    const auto same = r.shade({"--resume", "--set", "write.mode=resume"});
    EXPECT_EQ(same.exitCode, 0) << same.err;
    EXPECT_TRUE(fs::is_regular_file(db + "/time=3.exr"));
}

// mode overwrite removes only what Darkroom wrote, and refuses a folder it
// did not create before anything is shaded, twice for the same reason.
TEST(CinemaWriterRun, OverwriteRefusesAForeignFolderAndKeepsOtherFiles) {
    Shading r;
    const std::string db = r.dir.file("out/shaded.cdb");
    fs::create_directories(db);
    test::writeText(db + "/data.csv", "time,FILE\n1,time=1.exr\n");
    test::writeText(db + "/time=1.exr", "someone else's");
    const auto first = r.shade({"--set", "write.mode=overwrite"});
    EXPECT_EQ(first.exitCode, 2);
    EXPECT_THAT(first.err, HasSubstr("refusing to overwrite " + db));
    EXPECT_THAT(first.err, HasSubstr("Darkroom did not create it"));
    EXPECT_FALSE(fs::exists(db + "/.lock"));
    EXPECT_EQ(r.shade({"--set", "write.mode=overwrite"}).err, first.err);
    EXPECT_EQ(test::readText(db + "/time=1.exr"), "someone else's");

    fs::remove_all(db);
    ASSERT_EQ(r.shade().exitCode, 0);
    test::writeText(db + "/notes.txt", "mine");
    const auto again = r.shade({"--set", "write.mode=overwrite"});
    EXPECT_EQ(again.exitCode, 0) << again.err;
    EXPECT_EQ(test::readText(db + "/notes.txt"), "mine");
    EXPECT_EQ(CinemaDatabase::open(db).rowCount(), 3u);
}

// M5 (issue 26): with a CinemaWriter as the only per-entry sink, --index
// lists each entry with its product in the database written, one line each.
TEST(CinemaWriterRun, TheIndexListsTheProductsOfTheDatabaseWritten) {
    Shading r;
    const auto run = r.shade({"--index", r.dir.file("out/index.csv")});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(test::readText(r.dir.file("out/index.csv")),
              "time,FILE\n1,shaded.cdb/time=1.exr\n2,shaded.cdb/time=2.exr\n3,shaded.cdb/time=3.exr\n");
}

// L4 (issue 26): --set on an input that an edge feeds would be ignored (the
// edge wins): refused, naming the edge.
TEST(CinemaWriterRun, SetOnAnInputFedByAnEdgeIsRefused) {
    Shading r;
    const auto run = r.shade({"--set", "write.row=time=7"});
    EXPECT_EQ(run.exitCode, 2) << run.err;
    EXPECT_THAT(run.err, HasSubstr("input 'row' of node 'write' is fed by read.row"));
    EXPECT_FALSE(fs::exists(r.dir.file("out/shaded.cdb")));
}

namespace {

// Every file of a folder with its bytes, to show that nothing changed.
std::map<std::string, std::string> contentsOf(const std::string& folder) {
    std::map<std::string, std::string> out;
    for (const auto& e : fs::recursive_directory_iterator(folder))
        if (e.is_regular_file()) out[e.path().string()] = test::readText(e.path().string());
    return out;
}

}  // namespace

// D1 (issue 26): a writer pointed at the database its reader reads — the
// same folder, or one inside it — is refused before anything is written,
// with --foreach and without, and the source keeps every byte.
TEST(CinemaWriterRun, AWriterPointedAtItsReadersDatabaseIsRefused) {
    Shading r;
    const std::string source = r.dir.file("source.cdb");
    const auto before = contentsOf(source);
    const auto foreach = r.shade({"--set", "write.database=" + source, "--set", "write.mode=overwrite"});
    EXPECT_EQ(foreach.exitCode, 2) << foreach.err;
    EXPECT_THAT(foreach.err, HasSubstr("node 'write' (CinemaWriter): the output " + source + " is " + source +
                                       ", the database node 'read' reads; writing there would destroy the input"));
    EXPECT_EQ(contentsOf(source), before);

    const auto inside = r.shade({"--set", "write.database=" + source + "/shaded.cdb"});
    EXPECT_EQ(inside.exitCode, 2) << inside.err;
    EXPECT_THAT(inside.err, HasSubstr("lies inside " + source));
    EXPECT_EQ(contentsOf(source), before);

    // One evaluation, no --foreach: the evaluator refuses the path the node
    // resolves, naming the node upstream that read it.
    const auto once = test::runDarkroom({"-q", "run", r.dir.file("shade.yaml"), "-o", r.dir.file("out"), "--set",
                                         "write.database=" + source, "--set", "write.mode=overwrite"});
    EXPECT_EQ(once.exitCode, 2) << once.err;
    EXPECT_THAT(once.err, HasSubstr("the output " + source + " is " + source +
                                    ", which node 'read' upstream reads; writing there would destroy the input"));
    EXPECT_EQ(contentsOf(source), before);
}

// D6 (issue 26): the database records the pipeline that shaded it; a resume
// after the pipeline changed is refused before any shading, naming the node
// that changed, instead of mixing old and new entries. The same pipeline
// resumes.
TEST(CinemaWriterRun, AResumeAfterThePipelineChangedIsRefused) {
    Shading r;
    ASSERT_EQ(r.shade().exitCode, 0);
    const std::string db = r.dir.file("out/shaded.cdb");
    fs::remove(db + "/time=3.exr");
    const auto changed = r.shade({"--resume", "--set", "write.mode=resume", "--set", "read.strict=true"});
    EXPECT_EQ(changed.exitCode, 2) << changed.err;
    EXPECT_THAT(changed.err, HasSubstr("cannot resume " + db + ": the pipeline upstream of the writer changed since "
                                       "the database was begun (node 'read' (CinemaReader) changed)"));
    EXPECT_FALSE(fs::exists(db + "/time=3.exr"));
    EXPECT_FALSE(fs::exists(db + "/.lock"));
    const auto same = r.shade({"--resume", "--set", "write.mode=resume"});
    EXPECT_EQ(same.exitCode, 0) << same.err;
    EXPECT_TRUE(fs::is_regular_file(db + "/time=3.exr"));
}

// Issue 29 item 7: `darkroom run` has no --overwrite; the refusal names what
// does work, the node's mode parameter and the --set that sets it, alone
// and with --foreach.
TEST(CinemaWriterRun, TheRefusalAdvisesTheNodesModeNotAFlagRunLacks) {
    Shading r;
    ASSERT_EQ(r.shade().exitCode, 0);
    const std::string advice = "use mode: overwrite (--set write.mode=overwrite) to replace it or mode: resume "
                               "(--set write.mode=resume) to complete it";
    const auto each = r.shade();
    EXPECT_EQ(each.exitCode, 2) << each.err;
    EXPECT_THAT(each.err, HasSubstr("node 'write' (CinemaWriter): database " + r.dir.file("out/shaded.cdb") +
                                    " already exists and is not empty; " + advice));
    EXPECT_THAT(each.err, ::testing::Not(HasSubstr("--overwrite")));
    const auto once = test::runDarkroom({"-q", "run", r.dir.file("shade.yaml"), "-o", r.dir.file("out")});
    EXPECT_NE(once.exitCode, 0);
    EXPECT_THAT(once.err, HasSubstr("node 'write' (CinemaWriter): database " + r.dir.file("out/shaded.cdb") +
                                    " already exists and is not empty; " + advice));
    // The advice works.
    EXPECT_EQ(r.shade({"--set", "write.mode=overwrite"}).exitCode, 0);
}
