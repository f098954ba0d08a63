// CinemaReader through the registry, as a pipeline would run it.
#include "test_support.h"

#include <darkroom/error.h>
#include <darkroom/data/cinema/writer.h>
#include <darkroom/data/image_io.h>
#include <darkroom/core/run_filter.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstring>
#include <limits>

using namespace darkroom;
using ::testing::HasSubstr;

namespace {

FilterRunResult readEntry(const std::string& db, const std::string& parameters,
                          const std::string& file = "") {
    auto f = test::pluginRegistry().createFilter("CinemaReader");
    std::map<std::string, std::vector<Value>> in{{"database", {Value(db)}},
                                                 {"parameters", {Value(parameters)}}};
    if (!file.empty()) in["file"] = {Value(file)};
    return runFilter(*f, in);
}

bool samePixels(const Buffer& a, const Buffer& b) {
    if (a.width() != b.width() || a.height() != b.height() || a.channels() != b.channels()) return false;
    for (const auto& c : a.channels()) {
        const float* x = a.hostFloat(c.name);
        const float* y = b.hostFloat(c.name);
        if (!x || !y || std::memcmp(x, y, a.pixelCount() * sizeof(float)) != 0) return false;
    }
    return true;
}

}  // namespace

TEST(CinemaReader, ReadsAPngEntryAsColour) {
    const auto db = test::sharedData("cinema/sphere.cdb");
    if (db.empty()) GTEST_SKIP() << "../shared/data/cinema is absent";
    const auto r = readEntry(db, "phi=-162, theta=0");
    const auto& image = r.outputs.at("image").asImage();
    ASSERT_TRUE(image);
    EXPECT_EQ(image->width(), 519);
    EXPECT_EQ(image->height(), 422);
    EXPECT_TRUE(image->hasChannel("R") && image->hasChannel("G") && image->hasChannel("B"));
    EXPECT_TRUE(samePixels(*image, *readImage(db + "/image/-162/0.png")));
    EXPECT_TRUE(r.warnings.empty());
}

TEST(CinemaReader, EmptyParametersTakeTheFirstRowAndFileChoosesTheColumn) {
    const auto db = test::sharedData("cinema/multiple_artifacts.cdb");
    if (db.empty()) GTEST_SKIP() << "../shared/data/cinema is absent";
    const auto first = readEntry(db, "").outputs.at("image").asImage();
    EXPECT_TRUE(samePixels(*first, *readImage(db + "/image/-180/0.png")));
    const auto second = readEntry(db, "phi=-144", "FILE2").outputs.at("image").asImage();
    EXPECT_TRUE(samePixels(*second, *readImage(db + "/image_02/-144/0.png")));
}

TEST(CinemaReader, SnapsToTheNearestValueWithAWarning) {
    const auto db = test::sharedData("cinema/periodicPicture.cdb");
    if (db.empty()) GTEST_SKIP() << "../shared/data/cinema is absent";
    const auto r = readEntry(db, "angle=11");
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_THAT(r.warnings[0], HasSubstr("nearest value 10.8"));
    EXPECT_TRUE(samePixels(*r.outputs.at("image").asImage(), *readImage(db + "/data/pic32.0003.png")));
}

TEST(CinemaReader, ReadsBackWhatTheWriterWroteExactly) {
    test::TempDir dir;
    const auto path = dir.file("w.cdb");
    auto image = makeCpuBuffer(8, 6, {{"Z", ChannelType::Float32}, {"id", ChannelType::UInt32}});
    for (std::size_t i = 0; i < image->pixelCount(); ++i) {
        image->writeFloat("Z")[i] = float(i) * 0.25f;
        image->writeUInt("id")[i] = std::uint32_t(i * 3);
    }
    Camera cam;
    cam.width = 8;
    cam.height = 6;
    image->metadata().camera = cam;
    {
        CinemaWriter w(path, {"time", "phi"});
        w.addEntry({{"time", 0.5}, {"phi", -30}}, *image);
        w.addEntry({{"time", 0.5}, {"phi", 30}}, *makeCpuBuffer(8, 6, {{"Z", ChannelType::Float32}}));
        w.finish();
    }
    const auto r = readEntry(path, "time=0.5, phi=-30");
    // Besides what was written, the image names the product it was read from.
    const BufferPtr read = r.outputs.at("image").asImage();
    EXPECT_EQ(read->metadata().attributes.at("source"), path + "/time=0.5_phi=-30.exr");
    image->metadata().attributes["source"] = read->metadata().attributes.at("source");
    EXPECT_TRUE(identical(*read, *image));
}

TEST(CinemaReader, NoMatchNamesTheDatabaseAndListsValues) {
    const auto db = test::sharedData("cinema/sphere.cdb");
    if (db.empty()) GTEST_SKIP() << "../shared/data/cinema is absent";
    try {
        readEntry(db, "phi=500");
        FAIL() << "phi=500 is not in the database";
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("sphere.cdb"));
        EXPECT_THAT(e.what(), HasSubstr("-180, -162, -144"));
    }
    try {
        readEntry(db + "/../no-such.cdb", "");
        FAIL();
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("no-such.cdb"));
    }
}

TEST(CinemaReader, ReadsOneComposableLayerAsOneBuffer) {
    const auto db = test::sharedData("cinema/ttk_extracts_001.cdb");
    if (db.empty()) GTEST_SKIP() << "../shared/data/cinema is absent";
    const auto r = readEntry(db, "object=012");
    const auto& image = r.outputs.at("image").asImage();
    ASSERT_TRUE(image);
    EXPECT_EQ(image->channelNames(), (std::vector<std::string>{"Z", "Elevation", "SSSAO"}));
    EXPECT_EQ(image->width(), 1024);
    EXPECT_THAT(image->metadata().attributes.at("colormap.Elevation"), HasSubstr("blackbody.json"));
    EXPECT_EQ(image->requireFloat("Z")[0], std::numeric_limits<float>::infinity());  // corner is background
    // Normalised depth kept: recorded in the metadata, not a warning (the
    // depth-based passes say what they assume of it).
    EXPECT_TRUE(r.warnings.empty());
    EXPECT_THAT(image->metadata().attributes.at("depth.convention"), HasSubstr("normalised depth kept"));
    // SQL picks the layer too; a selection of both layers is refused with the choices.
    const auto sql = readEntry(db, "object > 5").outputs.at("image").asImage();
    EXPECT_EQ(sql->metadata().attributes.at("cis.layer"), "l001");
    try {
        readEntry(db, "CISChannel = 'CISDepth'");
        ADD_FAILURE() << "two layers were merged";
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("CISImage=i000, CISLayer=l000"));
    }
}

TEST(CinemaReader, SqlParametersPickTheFirstMatchingEntry) {
    const auto db = test::sharedData("cinema/sphere.cdb");
    if (db.empty()) GTEST_SKIP() << "../shared/data/cinema is absent";
    const auto r = readEntry(db, "phi > -170 AND phi < -150");
    EXPECT_TRUE(samePixels(*r.outputs.at("image").asImage(), *readImage(db + "/image/-162/0.png")));
}

TEST(CinemaReader, PeriodicPictureWithFileFirstAndSpacesAfterCommas) {
    const auto db = test::sharedData("cinema/periodicPicture.cdb");
    if (db.empty()) GTEST_SKIP() << "../shared/data/cinema is absent";
    const auto r = readEntry(db, "angle=7.2");
    EXPECT_TRUE(samePixels(*r.outputs.at("image").asImage(), *readImage(db + "/data/pic32.0002.png")));
}

TEST(CinemaReader, RowOutputHoldsTheEntryReadWithAbsoluteProductPaths) {
    test::TempDir dir;
    {
        CinemaWriter w(dir.file("rows.cdb"), {"time", "phi"});
        auto img = test::makeImage(3, 2, {"Z"}, [](int, int, int) { return 1.0f; });
        w.addEntry({{"time", CinemaValue(0.5)}, {"phi", CinemaValue(30.0)}}, *img);
        w.addEntry({{"time", CinemaValue(1.5)}, {"phi", CinemaValue(30.0)}}, *img);
        w.finish();
    }
    // A partial query: the row output is the whole row that was read (the
    // product path holds '=', so it is quoted).
    const auto r = readEntry(dir.file("rows.cdb"), "time=1.5");
    const Row& row = r.outputs.at("row").asRow();
    EXPECT_EQ(row, Row({{"time", "1.5"}, {"phi", "30"}, {"FILE", dir.file("rows.cdb/time=1.5_phi=30.exr")}}));
    EXPECT_EQ(formatRow(row), "time=1.5, phi=30, FILE=\"" + dir.file("rows.cdb/time=1.5_phi=30.exr") + "\"");
}

// --foreach and the editor's browser choose the entry by its row number;
// it overrides `parameters`, and a number past the last row is refused.
TEST(CinemaReader, EntryChoosesTheRowByNumber) {
    test::TempDir dir;
    {
        CinemaWriter w(dir.file("rows.cdb"), {"time"});
        for (const double t : {0.5, 1.5, 2.5}) {
            auto img = test::makeImage(2, 1, {"Z"}, [t](int, int, int) { return float(t); });
            w.addEntry({{"time", CinemaValue(t)}}, *img);
        }
        w.finish();
    }
    auto f = test::pluginRegistry().createFilter("CinemaReader");
    const auto read = [&](std::int64_t entry) {
        return runFilter(*f, {{"database", {Value(dir.file("rows.cdb"))}},
                              {"entry", {Value(entry)}},
                              {"parameters", {Value("time=0.5")}}});
    };
    const auto r = read(2);
    EXPECT_EQ(r.outputs.at("image").asImage()->hostFloat("Z")[0], 2.5f);
    EXPECT_EQ(*r.outputs.at("row").asRow().find("time"), "2.5");
    EXPECT_EQ(*read(-1).outputs.at("row").asRow().find("time"), "0.5");  // -1: by parameters
    try {
        read(3);
        ADD_FAILURE() << "entry 3 of 3 rows was read";
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("entry 3 is past the last row"));
        EXPECT_THAT(e.what(), HasSubstr("3 rows, numbered from 0"));
    }
}
