// ColorMapping's ranges beyond one image (issue 29): over a whole Cinema
// database (one scale for every entry; from CISChannelVarMin/Max, else a
// scan cached in the user's cache folder and invalidated by file stamps),
// symmetric about zero, clipped at percentiles; and a range below the
// float resolution of its values mapped to one colour.
#include "test_support.h"
#include "time_series_database.h"

#include <darkroom/error.h>
#include <darkroom/data/cinema/writer.h>
#include <darkroom/core/evaluator.h>
#include <darkroom/core/graph.h>
#include <darkroom/core/run_filter.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>

using namespace darkroom;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

namespace {

using Inputs = std::map<std::string, std::vector<Value>>;

FilterRunResult mapImage(const BufferPtr& image, Inputs extra) {
    auto f = test::pluginRegistry().createFilter("ColorMapping");
    extra["image"] = {Value(image)};
    return runFilter(*f, extra);
}

std::pair<double, double> used(const FilterRunResult& r) {
    return {r.outputs.at("usedMinimum").asFloat(), r.outputs.at("usedMaximum").asFloat()};
}

// The range ColorMapping used for each entry of `db` read by CinemaReader.
std::vector<std::pair<double, double>> rangesPerEntry(const std::string& db, std::size_t entries, double clip = 0) {
    Graph g(test::pluginRegistry());
    g.addNode("read", "CinemaReader");
    g.addNode("colour", "ColorMapping");
    g.setParameter("read", "database", Value(db));
    g.setParameter("colour", "channel", Value(std::string("value")));
    g.setParameter("colour", "range", Value(std::string("database")));
    g.setParameter("colour", "clip", Value(clip));
    g.connect({"read", "image"}, {"colour", "image"});
    Evaluator ev;
    std::vector<std::pair<double, double>> out;
    for (std::size_t e = 0; e < entries; ++e) {
        g.setParameter("read", "entry", Value(std::int64_t(e)));
        out.emplace_back(ev.evaluate(g, "colour", "usedMinimum").asFloat(),
                         ev.evaluate(g, "colour", "usedMaximum").asFloat());
    }
    return out;
}

struct CacheHome {
    test::TempDir dir;
    CacheHome() { setenv("XDG_CACHE_HOME", dir.path().c_str(), 1); }
    ~CacheHome() { unsetenv("XDG_CACHE_HOME"); }
    std::size_t files() const {
        const fs::path ranges = fs::path(dir.path()) / "darkroom" / "ranges";
        return fs::exists(ranges) ? std::size_t(std::distance(fs::directory_iterator(ranges), {})) : 0;
    }
};

}  // namespace

TEST(ColorRange, EveryEntryOfADatabaseSharesOneScaleAndAChangeIsSeen) {
    CacheHome cache;
    test::TempDir dir;
    const std::string db = dir.file("series.cdb");
    test::writeTimeSeriesDatabase(db, {1.0, 2.0, 3.0});  // entry t holds value t everywhere
    for (const auto& r : rangesPerEntry(db, 3)) EXPECT_EQ(r, std::make_pair(1.0, 3.0));
    EXPECT_EQ(cache.files(), 1u);  // the scan, remembered
    // Another state of the database is another scan: the stamps changed.
    fs::remove_all(db);
    test::writeTimeSeriesDatabase(db, {1.0, 2.0, 5.0});
    for (const auto& r : rangesPerEntry(db, 3)) EXPECT_EQ(r, std::make_pair(1.0, 5.0));
}

TEST(ColorRange, TheDatabaseRangeClippedAtPercentilesOfEveryEntrysValues) {
    CacheHome cache;
    test::TempDir dir;
    const std::string db = dir.file("series.cdb");
    // Four entries of 50 x 20 values spread unevenly, one entry with a far
    // outlier that a plain minimum and maximum would spread the map over.
    std::vector<double> all;
    {
        CinemaWriter w(db, {"time"});
        for (int t = 0; t < 4; ++t) {
            const auto img = test::makeImage(50, 20, {"Z", "value"}, [t](int x, int y, int c) {
                if (c == 0) return 1.0f;
                if (t == 2 && x == 0 && y == 0) return 1e7f;
                return float(std::pow(double(x + 50 * y) / 999.0, 3.0) * (t + 1));
            });
            for (std::size_t i = 0; i < img->pixelCount(); ++i) all.push_back(img->hostFloat("value")[i]);
            w.addEntry({{"time", CinemaValue(double(t))}}, *img);
        }
        w.finish();
    }
    std::sort(all.begin(), all.end());
    const auto exact = [&all](double q) { return all[std::size_t(std::llround(q * double(all.size() - 1)))]; };
    // Two levels of 2^16 bins over [0, 1e7]: within 1e7 / 2^32 of the exact rank.
    const double tolerance = 1e7 / 4294967296.0 * 2;
    for (const auto& [low, high] : rangesPerEntry(db, 4, 2.0)) {
        EXPECT_NEAR(low, exact(0.02), tolerance);
        EXPECT_NEAR(high, exact(0.98), tolerance);
        EXPECT_LT(high, 5.0);  // the outlier is out
    }
    // Remembered beside the plain range, which it did not replace.
    for (const auto& r : rangesPerEntry(db, 4)) EXPECT_EQ(r, std::make_pair(all.front(), all.back()));
}

TEST(ColorRange, AComposableSetsStatedRangeIsUsedWithoutReadingAProduct) {
    CacheHome cache;
    test::TempDir dir;
    fs::create_directories(dir.file("cis.cdb"));
    // Products that are not there: the range comes from the columns alone.
    test::writeText(dir.file("cis.cdb/data.csv"),
                    "time,CISChannelVar,CISChannelVarMin,CISChannelVarMax,FILE\n"
                    "0,heat,-2,5,a.npz\n1,heat,-4,3,b.npz\n0,other,-100,100,c.npz\n");
    auto img = test::makeImage(2, 1, {"heat"}, [](int x, int, int) { return float(x); });
    img->metadata().attributes["source"] = dir.file("cis.cdb/a.npz");
    const auto r = mapImage(img, {{"channel", {Value("heat")}}, {"range", {Value("database")}}});
    EXPECT_EQ(used(r), std::make_pair(-4.0, 5.0));
    EXPECT_EQ(cache.files(), 0u);
}

TEST(ColorRange, WithoutADatabaseTheDatabaseRangeSaysWhy) {
    auto img = test::makeImage(2, 1, {"v"}, [](int x, int, int) { return float(x); });
    try {
        mapImage(img, {{"channel", {Value("v")}}, {"range", {Value("database")}}});
        FAIL() << "no database, yet a range";
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("the image names no source product"));
    }
    img->metadata().attributes["source"] = "/nowhere/at/all.exr";
    EXPECT_THROW(mapImage(img, {{"channel", {Value("v")}}, {"range", {Value("database")}}}), Error);
}

TEST(ColorRange, SymmetricAboutZeroAndClippedAtPercentiles) {
    // -1 .. 3: symmetric gives [-3, 3].
    auto a = test::makeImage(5, 1, {"v"}, [](int x, int, int) { return float(x) - 1.0f; });
    EXPECT_EQ(used(mapImage(a, {{"channel", {Value("v")}}, {"symmetric", {Value(true)}}})), std::make_pair(-3.0, 3.0));
    // 0 .. 99 and one outlier: clipping 1 % at each end leaves the outlier out.
    auto b = test::makeImage(101, 1, {"v"}, [](int x, int, int) { return x == 100 ? 1e6f : float(x); });
    const auto [low, high] = used(mapImage(b, {{"channel", {Value("v")}}, {"clip", {Value(1.0)}}}));
    EXPECT_EQ(low, 1.0);
    EXPECT_EQ(high, 99.0);
    EXPECT_EQ(used(mapImage(b, {{"channel", {Value("v")}}})).second, 1e6);  // not clipped by default
    EXPECT_THROW(mapImage(a, {{"channel", {Value("v")}}, {"symmetric", {Value(true)}}, {"scale", {Value("log")}}}),
                 Error);
}

TEST(ColorRange, ARangeBelowTheFloatResolutionMapsToOneColour) {
    // A near-constant field: its values differ only in the last bits.
    auto img = test::makeImage(4, 1, {"v"}, [](int x, int, int) { return x % 2 ? std::nextafter(1000.0f, 2000.0f) : 1000.0f; });
    const auto r = mapImage(img, {{"channel", {Value("v")}}});
    const auto [low, high] = used(r);
    EXPECT_EQ(low, high);
    const Buffer& out = *r.outputs.at("image").asImage();
    for (std::size_t i = 1; i < 4; ++i) EXPECT_NEAR(out.hostFloat("R")[i], out.hostFloat("R")[0], 1e-6);
}
