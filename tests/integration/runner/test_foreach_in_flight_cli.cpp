// `darkroom run --foreach` with several entries in flight (issue 32 item 1):
// the outputs — a database a CinemaWriter fills (data.csv, its marker, every
// product), per-entry pictures named from their rows, the index — are those
// of a run that shades one entry at a time, byte for byte; and so are they
// after a run with entries in flight failed part way and a resume completed
// it. The colour scale spans the database (range: database), so every entry
// depends on the first entry's scan, made once.
#include "runner_process.h"
#include "test_support.h"
#include "time_series_database.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

using namespace darkroom;
namespace fs = std::filesystem;

namespace {

// `range`: ColorMapping's (database: every entry reads the first one's scan).
std::string pipeline(const std::string& range) {
    return R"(darkroom: 1
nodes:
  read: {type: CinemaReader, parameters: {database: series.cdb}}
  colour: {type: ColorMapping, parameters: {channel: value, range: )" + range + R"(, colormap: cool-to-warm}}
  store: {type: CinemaWriter, parameters: {database: shaded.cdb, format: png, mode: resume}}
  picture: {type: ImageWriter, parameters: {path: "frames/t{time}.png"}}
edges:
  - read.image -> colour.image
  - colour.image -> store.image
  - read.row -> store.row
  - colour.image -> picture.image
)";
}

struct Series {
    test::TempDir dir;
    std::vector<double> times;
    explicit Series(const std::string& range) {
        for (int k = 0; k < 11; ++k) times.push_back(0.25 * k - 1.0);
        test::writeTimeSeriesDatabase(dir.file("series.cdb"), times);
        test::writeText(dir.file("p.yaml"), pipeline(range));
    }
    test::ProcessResult shade(const std::string& inFlight, std::vector<std::string> more = {}) const {
        std::vector<std::string> args{"-q", "run", dir.file("p.yaml"), "--foreach", "read", "--in-flight", inFlight,
                                      "--index", dir.file("out/index.csv"), "--output", dir.file("out")};
        args.insert(args.end(), more.begin(), more.end());
        return test::runDarkroom(args, {"XDG_CACHE_HOME=" + dir.file("cache")});
    }
    // The outputs of a run, moved aside as `name` for the next run.
    std::string keep(const std::string& name) const {
        fs::rename(dir.file("out"), dir.file(name));
        return dir.file(name);
    }
};

}  // namespace

TEST(ForeachInFlight, OutputsAreThoseOfOneEntryAtATime) {
    Series s("database");
    const auto serial = s.shade("1");
    ASSERT_EQ(serial.exitCode, 0) << serial.err;
    const std::string reference = s.keep("serial");
    ASSERT_TRUE(fs::is_regular_file(reference + "/shaded.cdb/data.csv"));
    ASSERT_TRUE(fs::is_regular_file(reference + "/frames/t1.5.png"));
    for (const std::string n : {"2", "4", "0"}) {
        SCOPED_TRACE("--in-flight " + n);
        const auto overlapped = s.shade(n);
        ASSERT_EQ(overlapped.exitCode, 0) << overlapped.err;
        EXPECT_EQ(overlapped.err, "");
        EXPECT_FALSE(fs::exists(s.dir.file("out/shaded.cdb.staging")));
        EXPECT_EQ(test::compareFolders(reference, s.dir.file("out")), "");
        fs::remove_all(s.dir.file("out"));
    }
}

TEST(ForeachInFlight, AResumeAfterAFailurePartWayGivesTheSameOutputs) {
    Series s("automatic");  // a database range would refuse the broken entry at the first
    ASSERT_EQ(s.shade("1").exitCode, 0);
    const std::string reference = s.keep("serial");
    // Entry 7 of 11 cannot be read: the run stops there, keeping what the
    // lanes shaded (the first lane's in the database, the others' merged).
    const std::string broken = s.dir.file("series.cdb/time=0.5.exr");
    fs::rename(broken, broken + ".aside");
    test::writeText(broken, "not an image");
    const auto failed = s.shade("3");
    EXPECT_NE(failed.exitCode, 0);
    EXPECT_NE(failed.err.find("entry time=0.5"), std::string::npos) << failed.err;
    EXPECT_FALSE(fs::exists(s.dir.file("out/shaded.cdb.staging")));
    fs::remove(broken);
    fs::rename(broken + ".aside", broken);
    const auto resumed = s.shade("3", {"--resume"});
    ASSERT_EQ(resumed.exitCode, 0) << resumed.err;
    EXPECT_EQ(test::compareFolders(reference, s.dir.file("out")), "");
}
