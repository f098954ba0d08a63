// Movie: an MP4 decoded back with FFmpeg has one frame per entry, the size and
// frame rate asked for, the frames in the entries' sorted order (each frame a
// grey whose level encodes its time) and the grey levels of BT.709 limited
// range; subsets, explicit order, odd sizes, errors.
#include "decoded_movie.h"
#include "test_support.h"

#include <darkroom/error.h>
#include <darkroom/data/image_io.h>
#include <darkroom/core/run_filter.h>
#include <darkroom/srgb.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

using namespace darkroom;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

namespace {

using Inputs = std::map<std::string, std::vector<Value>>;

// A database whose data.csv lists its rows out of time order: time t is a
// uniform grey of sRGB level 0.1 + 0.1 t (so decoded brightness tells the order).
std::string greyDatabase(const test::TempDir& dir, int w, int h, const std::vector<int>& times) {
    const std::string db = dir.file("frames.cdb");
    fs::create_directories(db);
    std::string csv = "time,view,FILE\n";
    for (int t : times)
        for (const char* view : {"front", "side"}) {
            const std::string name = "t" + std::to_string(t) + "_" + view + ".png";
            const float level = srgbToLinear(0.1f + 0.1f * float(t));
            writeImage(*test::makeImage(w, h, {"R", "G", "B"}, [&](int, int, int) { return level; }), db + "/" + name);
            csv += std::to_string(t) + "," + view + "," + name + "\n";
        }
    test::writeText(db + "/data.csv", csv);
    return db;
}

void makeMovie(const std::string& db, const std::string& out, Inputs extra = {}) {
    auto f = test::pluginRegistry().createFilter("Movie");
    extra["database"] = {Value(db)};
    extra["path"] = {Value(out)};
    runFilter(*f, extra);
}

// Limited-range BT.709 luma of a grey of sRGB level v (R = G = B).
double lumaOf(double v) { return 16.0 + 219.0 * v; }

}  // namespace

TEST(Movie, DecodesToOneFramePerEntryInSortedOrder) {
    test::TempDir dir;
    const std::string db = greyDatabase(dir, 64, 48, {3, 0, 6, 1, 5, 2, 4});
    const std::string mp4 = dir.file("out/movie.mp4");
    makeMovie(db, mp4, {{"where", {Value("view=front")}}, {"frameRate", {Value(12.0)}}});
    const auto m = test::decodeMovie(mp4);
    EXPECT_EQ(m.codec, "h264");
    EXPECT_THAT(m.container, HasSubstr("mp4"));
    EXPECT_EQ(m.frames(), 7);
    EXPECT_EQ(m.width, 64);
    EXPECT_EQ(m.height, 48);
    EXPECT_NEAR(m.frameRate, 12.0, 1e-9);
    for (int t = 0; t < m.frames(); ++t) EXPECT_NEAR(m.meanLuma[std::size_t(t)], lumaOf(0.1 + 0.1 * t), 2.0) << t;
    // No temporary file is left beside the movie.
    int files = 0;
    for (const auto& e : fs::directory_iterator(dir.file("out"))) files += int(e.is_regular_file());
    EXPECT_EQ(files, 1);
}

TEST(Movie, AllEntriesOrderedByTheGivenColumns) {
    test::TempDir dir;
    const std::string db = greyDatabase(dir, 32, 32, {2, 0, 1});
    const std::string mp4 = dir.file("all.mp4");
    // Default order: every parameter column left to right (time, then view).
    makeMovie(db, mp4);
    auto m = test::decodeMovie(mp4);
    ASSERT_EQ(m.frames(), 6);
    for (int k = 0; k < 6; ++k) EXPECT_NEAR(m.meanLuma[std::size_t(k)], lumaOf(0.1 + 0.1 * (k / 2)), 2.0) << k;
    // view first: the three "front" frames, then the three "side" ones, each by time.
    makeMovie(db, mp4, {{"orderBy", {Value("view, time")}}});
    m = test::decodeMovie(mp4);
    ASSERT_EQ(m.frames(), 6);
    for (int k = 0; k < 6; ++k) EXPECT_NEAR(m.meanLuma[std::size_t(k)], lumaOf(0.1 + 0.1 * (k % 3)), 2.0) << k;
}

TEST(Movie, OddSizesArePaddedToEven) {
    test::TempDir dir;
    const std::string db = greyDatabase(dir, 33, 21, {0, 1});
    makeMovie(db, dir.file("odd.mp4"));
    const auto m = test::decodeMovie(dir.file("odd.mp4"));
    EXPECT_EQ(m.width, 34);
    EXPECT_EQ(m.height, 22);
    EXPECT_EQ(m.frames(), 4);
}

TEST(Movie, ErrorsAreClear) {
    test::TempDir dir;
    const std::string db = greyDatabase(dir, 16, 16, {0, 1});
    writeImage(*test::makeImage(8, 8, {"R", "G", "B"}, [](int, int, int) { return 0.5f; }), db + "/t1_side.png");
    auto message = [&](Inputs in) {
        try {
            makeMovie(db, dir.file("e.mp4"), in);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_THAT(message({}), HasSubstr("every frame needs one size"));
    EXPECT_THAT(message({{"where", {Value("view=top")}}}), HasSubstr("no entry"));
    EXPECT_THAT(message({{"orderBy", {Value("speed")}}}), HasSubstr("speed"));
    EXPECT_FALSE(fs::exists(dir.file("e.mp4")));
}
