// `darkroom run --foreach` output paths with {column} placeholders (issue 29
// item 7): each entry's file is named from its own row, a placeholder naming
// no column stops the run before anything is written, and a pattern that
// gives two entries one file is refused instead of overwriting.
#include "runner_process.h"
#include "test_support.h"
#include "time_series_database.h"

#include <darkroom/data/cinema/writer.h>
#include <darkroom/data/image_io.h>

#include <gtest/gtest.h>

#include <filesystem>

using namespace darkroom;
namespace fs = std::filesystem;

namespace {

std::string pipeline(const std::string& output) {
    return "darkroom: 1\nnodes:\n"
           "  read: {type: CinemaReader, parameters: {database: series.cdb}}\n"
           "  write: {type: ImageWriter, parameters: {path: \"" + output + "\"}}\n"
           "edges:\n"
           "  - read.image -> write.image\n";
}

test::ProcessResult runWith(const test::TempDir& dir, const std::string& output) {
    test::writeText(dir.file("p.yaml"), pipeline(output));
    return test::runDarkroom({"run", dir.file("p.yaml"), "--foreach", "read", "--output", dir.file("out")});
}

// The value of channel `value` of the file's first pixel: the source entry's time.
float timeIn(const std::string& file) { return readImage(file)->hostFloat("value")[0]; }

}  // namespace

TEST(OutputPlaceholders, AColumnNamesEachEntrysFile) {
    test::TempDir dir;
    test::writeTimeSeriesDatabase(dir.file("series.cdb"), {0.5, -2.0, 3.0});
    const auto r = runWith(dir, "frames/t{time}.exr");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_FLOAT_EQ(timeIn(dir.file("out/frames/t0.5.exr")), 0.5f);
    EXPECT_FLOAT_EQ(timeIn(dir.file("out/frames/t-2.exr")), -2.0f);
    EXPECT_FLOAT_EQ(timeIn(dir.file("out/frames/t3.exr")), 3.0f);
    EXPECT_FALSE(fs::exists(dir.file("out/frames/t{time}.exr")));
}

TEST(OutputPlaceholders, AValueStartingAFileNameCannotReadAsAnOptionOrHiddenFile) {
    test::TempDir dir;
    test::writeTimeSeriesDatabase(dir.file("series.cdb"), {-2.0});
    const auto r = runWith(dir, "{time}_{entry}.exr");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_FLOAT_EQ(timeIn(dir.file("out/~2_time=-2.exr")), -2.0f);
}

TEST(OutputPlaceholders, AnUnknownColumnStopsTheRunNamingTheColumns) {
    test::TempDir dir;
    test::writeTimeSeriesDatabase(dir.file("series.cdb"), {1.0, 2.0});
    const auto r = runWith(dir, "frames/{phi}.exr");
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("{phi}"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("time"), std::string::npos) << r.err;  // the columns it has
    EXPECT_FALSE(fs::exists(dir.file("out/frames")));
}

TEST(OutputPlaceholders, TwoEntriesGivenOneFileAreRefusedBeforeAnyIsWritten) {
    test::TempDir dir;
    {
        CinemaWriter w(dir.file("series.cdb"), {"time", "phi"});
        for (const double t : {1.0, 2.0})
            for (const double phi : {0.0, 90.0})
                w.addEntry({{"time", CinemaValue(t)}, {"phi", CinemaValue(phi)}},
                           *test::makeImage(4, 2, {"Z", "value"}, [=](int, int, int) { return float(t); }));
        w.finish();
    }
    const auto r = runWith(dir, "frames/{time}.exr");
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("would both be written to"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir.file("out/frames/1.exr")));
}
