// What `darkroom run --foreach` does with <database>.staging, the folder in
// which ranks stage their entries (darkroom/workflows/written_databases.h): it never
// deletes one Darkroom did not make (D5 of issue 26) and never takes in a
// staged file from outside its staging databases (S2).
#include "../../../tests/integration/runner/runner_process.h"
#include "test_support.h"
#include "time_series_database.h"

#include <darkroom/data/cinema/database.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

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

struct Staging {
    test::TempDir dir;
    std::string db = dir.file("out/shaded.cdb");
    std::string staging = db + ".staging";
    Staging() {
        test::writeTimeSeriesDatabase(dir.file("source.cdb"), {1.0, 2.0});
        test::writeText(dir.file("shade.yaml"), kPipeline);
    }
    test::ProcessResult shade(std::vector<std::string> more = {}) const {
        std::vector<std::string> args{"-q", "run", dir.file("shade.yaml"), "--foreach", "read", "-o", dir.file("out")};
        args.insert(args.end(), more.begin(), more.end());
        return test::runDarkroom(args);
    }
    // A staging database as a rank would leave it (the database's own marker
    // copied in), with the marker a run over ranks puts in the staging folder.
    void plantStaged(const std::string& csv) const {
        fs::create_directories(staging + "/rank-0");
        test::writeText(staging + "/.darkroom-staging", "");
        fs::copy_file(db + "/.darkroom-database", staging + "/rank-0/.darkroom-database",
                      fs::copy_options::overwrite_existing);
        test::writeText(staging + "/rank-0/data.csv", csv);
    }
};

}  // namespace

TEST(CinemaWriterStaging, AFolderDarkroomDidNotMakeIsNeverDeleted) {
    for (const char* mode : {"create", "overwrite", "resume"}) {
        Staging s;
        fs::create_directories(s.staging + "/results");
        test::writeText(s.staging + "/results/table.txt", "mine");
        const auto run = s.shade({"--set", std::string("write.mode=") + mode});
        EXPECT_EQ(run.exitCode, 2) << mode << ": " << run.err;
        EXPECT_THAT(run.err, HasSubstr(s.staging));
        EXPECT_THAT(run.err, HasSubstr("Darkroom did not make it"));
        EXPECT_EQ(test::readText(s.staging + "/results/table.txt"), "mine") << mode;
    }
    Staging file;
    fs::create_directories(file.dir.file("out"));
    test::writeText(file.staging, "a file of the same name");
    EXPECT_EQ(file.shade().exitCode, 2);
    EXPECT_EQ(test::readText(file.staging), "a file of the same name");
}

TEST(CinemaWriterStaging, AStagedEntryNamingAFileOutsideIsRefusedAndTheFileKept) {
    Staging s;
    ASSERT_EQ(s.shade().exitCode, 0);
    fs::create_directories(s.dir.file("elsewhere"));
    const std::string secret = s.dir.file("elsewhere/secret.txt");
    test::writeText(secret, "secret");
    for (const std::string& cell : std::vector<std::string>{"../../../elsewhere/secret.txt", s.dir.file("elsewhere/secret.txt"), "..",
                                   "sub/../../../../elsewhere/secret.txt"}) {
        s.plantStaged("time,FILE\n9," + cell + "\n");
        const auto run = s.shade({"--resume", "--set", "write.mode=resume"});
        EXPECT_NE(run.exitCode, 0) << cell;
        EXPECT_THAT(run.err, HasSubstr("not a file name inside the staging database")) << cell;
        EXPECT_EQ(test::readText(secret), "secret") << cell;
        EXPECT_EQ(CinemaDatabase::open(s.db).rowCount(), 2u) << cell;
    }
    // A link inside the staging database is not a staged product either.
    s.plantStaged("time,FILE\n9,time=9.exr\n");
    fs::create_symlink(secret, s.staging + "/rank-0/time=9.exr");
    const auto link = s.shade({"--resume", "--set", "write.mode=resume"});
    EXPECT_NE(link.exitCode, 0);
    EXPECT_THAT(link.err, HasSubstr("not a plain file"));
    EXPECT_EQ(test::readText(secret), "secret");
    EXPECT_EQ(CinemaDatabase::open(s.db).rowCount(), 2u);
}
