// One colour scale per database, end to end (issue 29): `darkroom run
// --foreach` over a time series whose entries hold different values, with
// ColorMapping's range over the whole database feeding a ColorLegend, draws
// the same legend for every entry (byte-identical files), where the
// per-image automatic range draws a different one for each.
#include "runner_process.h"
#include "test_support.h"
#include "time_series_database.h"

#include <darkroom/data/image_io.h>

#include <gtest/gtest.h>

#include <filesystem>

using namespace darkroom;
namespace fs = std::filesystem;

namespace {

// Per entry: the legend of the entry's colour mapping, drawn on one fixed
// grey image (so that only the legend can differ), written to legend_<entry>.png.
std::string pipeline(const std::string& range) {
    return "darkroom: 1\nnodes:\n"
           "  read: {type: CinemaReader, parameters: {database: series.cdb}}\n"
           "  colour: {type: ColorMapping, parameters: {channel: value, range: " + range + "}}\n"
           "  canvas: {type: ImageReader, parameters: {path: grey.exr}}\n"
           "  legend: {type: ColorLegend, parameters: {title: value}}\n"
           "  write: {type: ImageWriter, parameters: {path: legend.png}}\n"
           "edges:\n"
           "  - read.image -> colour.image\n"
           "  - canvas.image -> legend.image\n"
           "  - colour.usedMinimum -> legend.minimum\n"
           "  - colour.usedMaximum -> legend.maximum\n"
           "  - legend.image -> write.image\n";
}

std::vector<std::string> legends(const test::TempDir& dir, const std::string& range, const std::string& out,
                                 const std::string& where = "") {
    test::writeText(dir.file(range + ".yaml"), pipeline(range));
    std::vector<std::string> args{"run", dir.file(range + ".yaml"), "--foreach", "read", "--output", dir.file(out)};
    if (!where.empty()) args.insert(args.end(), {"--where", where});
    const auto r = test::runDarkroom(args, {"XDG_CACHE_HOME=" + dir.file("cache")});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    std::vector<std::string> files;
    for (const char* t : {"1", "2", "3"})
        if (fs::exists(dir.file(out + "/legend_time=" + t + ".png")))
            files.push_back(test::readText(dir.file(out + "/legend_time=" + t + ".png")));
    return files;
}

}  // namespace

TEST(DatabaseRangeCli, EveryEntryOfAForeachRunGetsTheSameLegend) {
    test::TempDir dir;
    test::writeTimeSeriesDatabase(dir.file("series.cdb"), {1.0, 2.0, 3.0});
    writeImage(*test::makeImage(160, 120, {"R", "G", "B"}, [](int, int, int) { return 0.5f; }), dir.file("grey.exr"));
    const auto same = legends(dir, "database", "database");
    ASSERT_FALSE(same[0].empty());
    EXPECT_EQ(same[1], same[0]);
    EXPECT_EQ(same[2], same[0]);
    // The contrast: one range per image gives each entry its own legend.
    const auto own = legends(dir, "automatic", "automatic");
    ASSERT_FALSE(own[0].empty());
    EXPECT_NE(own[1], own[0]);
    EXPECT_NE(own[0], same[0]);
}

TEST(DatabaseRangeCli, AWhereSelectionIsTheRangeOfItsOwnEntries) {
    test::TempDir dir;
    test::writeTimeSeriesDatabase(dir.file("series.cdb"), {1.0, 2.0, 3.0});
    writeImage(*test::makeImage(160, 120, {"R", "G", "B"}, [](int, int, int) { return 0.5f; }), dir.file("grey.exr"));
    const auto all = legends(dir, "database", "all");
    const auto firstTwo = legends(dir, "database", "first-two", "time < 3");
    ASSERT_EQ(all.size(), 3u);
    ASSERT_EQ(firstTwo.size(), 2u);  // only the selected entries were shaded
    EXPECT_EQ(firstTwo[1], firstTwo[0]);  // one scale for the selection: [1, 2]
    EXPECT_NE(firstTwo[0], all[0]);       // not the whole database's [1, 3]
    // The same selection again is the same scale (remembered per selection).
    EXPECT_EQ(legends(dir, "database", "again", "time < 3"), firstTwo);
}
