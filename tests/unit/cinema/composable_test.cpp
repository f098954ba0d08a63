// Composable image sets: grouping and depth conversion on the real TTK
// database and on small sets written here (offsets, near/far, Ascent NaN).
#include "test_support.h"

#include <darkroom/error.h>
#include <darkroom/data/cinema/composable.h>
#include <darkroom/data/formats/npy.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>

using namespace darkroom;
using ::testing::HasSubstr;

namespace {

const float kInf = std::numeric_limits<float>::infinity();

}  // namespace

TEST(ComposableImageSet, TtkExtractsGroupIntoOneImageWithTwoLayers) {
    const auto path = test::sharedData("cinema/ttk_extracts_001.cdb");
    if (path.empty()) GTEST_SKIP() << "../shared/data/cinema is absent";
    const auto db = CinemaDatabase::open(path);
    ASSERT_TRUE(isComposableImageSet(db));
    const auto images = composableImages(db);
    ASSERT_EQ(images.size(), 1u);
    EXPECT_EQ(images[0].id, "i000");
    EXPECT_EQ(images[0].width, 1024);
    ASSERT_EQ(images[0].layers.size(), 2u);
    const auto& l0 = images[0].layers[0];
    EXPECT_EQ(l0.id, "l000");
    EXPECT_EQ(l0.parameters, "object=000");
    ASSERT_EQ(l0.channels.size(), 3u);
    EXPECT_EQ(l0.channels[0].bufferName(), "Z");
    EXPECT_EQ(l0.channels[1].bufferName(), "Elevation");
    EXPECT_EQ(l0.channels[2].bufferName(), "SSSAO");
    EXPECT_EQ(std::filesystem::path(l0.channels[1].colormap).filename(), "cooltowarm.json");
    EXPECT_EQ(std::filesystem::path(images[0].layers[1].channels[1].colormap).filename(), "blackbody.json");
}

TEST(ComposableImageSet, TtkDepthBecomesZWithInfiniteBackgroundAndKeepsOrdering) {
    const auto path = test::sharedData("cinema/ttk_extracts_001.cdb");
    if (path.empty()) GTEST_SKIP() << "../shared/data/cinema is absent";
    const auto db = CinemaDatabase::open(path);
    Diagnostics warnings;
    const auto a = readComposableRows(db, db.selectWhere("object=000"), &warnings);
    const auto b = readComposableRows(db, db.query("object = '012'"), &warnings);
    // No camera in data.csv: Z stays normalised, which the buffer records;
    // a depth-based pass says what it assumes (sdk depth_input.h), the reader
    // warns about nothing.
    EXPECT_TRUE(warnings.empty());
    EXPECT_THAT(a->metadata().attributes.at("depth.convention"), HasSubstr("normalised depth kept"));
    EXPECT_EQ(a->channelNames(), (std::vector<std::string>{"Z", "Elevation", "SSSAO"}));
    EXPECT_EQ(a->metadata().attributes.at("colormap.Elevation"),
              (std::filesystem::path(path) / "colormap/cooltowarm.json").lexically_normal().string());
    EXPECT_EQ(b->metadata().attributes.at("cis.layer"), "l001");
    const float* za = a->requireFloat("Z");
    const float* zb = b->requireFloat("Z");
    // The .npz arrays are [x][y] (shape = width, height): value (x, y) at x * 1024 + y.
    const auto depthA = readNpz(path + "/000_Depth.npz").front().values;
    const auto depthB = readNpz(path + "/012_Depth.npz").front().values;
    std::size_t background = 0, both = 0;
    for (std::size_t x = 0; x < 1024; ++x)
        for (std::size_t y = 0; y < 1024; ++y) {
            const std::size_t k = x * 1024 + y, i = y * 1024 + x;
            if (depthA[k] == 1.0f) {
                ++background;
                EXPECT_EQ(za[i], kInf) << "pixel " << i;
                EXPECT_TRUE(std::isnan(a->requireFloat("Elevation")[i]));
            } else {
                EXPECT_TRUE(std::isfinite(za[i]));
            }
            if (depthA[k] < 1.0f && depthB[k] < 1.0f) {
                ++both;
                // The nearer object (smaller stored depth) has the smaller Z.
                EXPECT_EQ(za[i] < zb[i], depthA[k] < depthB[k]) << "pixel " << i;
            }
        }
    EXPECT_EQ(background, 874251u);  // counted independently from the .npz
    EXPECT_GT(both, 1000u);          // the objects overlap on screen
}

TEST(ComposableImageSet, OffsetsNearFarAndAsciiNaNDepthAreConverted) {
    test::TempDir dir;
    namespace fs = std::filesystem;
    fs::create_directories(dir.file("s.cdb"));
    const std::string db = dir.file("s.cdb");
    // Layer a: TTK depth 2x2 at offset (1, 1) in a 4x3 image, near 2 far 6;
    // [x][y]: (0,0) = 0, (0,1) = 0.5, (1,0) = 1, (1,1) = 0.25.
    writeNpz(db + "/a_depth.npz", {NpyArray{"data", "<f4", {2, 2}, false, {0.0f, 0.5f, 1.0f, 0.25f}}});
    writeNpz(db + "/a_val.npz", {NpyArray{"data", "<f4", {2, 2}, false, {1, 2, 3, 4}}});
    // Layer b: Ascent-style raw distance with NaN background, full image.
    std::vector<float> raw(12, 7.5f);
    raw[5] = std::numeric_limits<float>::quiet_NaN();
    writeNpz(db + "/b_depth.npz", {NpyArray{"data", "<f4", {4, 3}, false, raw}});  // x = 1, y = 2 is NaN
    test::writeText(db + "/data.csv",
                    "object,CamNear,CamFar,CISImage,CISImageWidth,CISImageHeight,CISLayer,CISLayerWidth,"
                    "CISLayerHeight,CISLayerOffsetX,CISLayerOffsetY,CISChannel,CISChannelVar,FILE\n"
                    "a,2,6,i0,4,3,la,2,2,1,1,CISDepth,Depth,a_depth.npz\n"
                    "a,2,6,i0,4,3,la,2,2,1,1,value,Value,a_val.npz\n"
                    "b,,,i0,4,3,lb,4,3,0,0,CISDepth,depth,b_depth.npz\n");
    const auto cdb = CinemaDatabase::open(db);
    Diagnostics warnings;
    const auto a = readComposableRows(cdb, cdb.select(CinemaDatabase::parseQuery("object=a")), &warnings);
    EXPECT_TRUE(warnings.empty());  // near/far known: nothing to warn about
    const float* z = a->requireFloat("Z");
    const float* v = a->requireFloat("Value");
    EXPECT_EQ(z[0], kInf);  // outside the layer
    EXPECT_TRUE(std::isnan(v[0]));
    EXPECT_FLOAT_EQ(z[1 * 4 + 1], 2.0f);   // d = 0 -> near
    EXPECT_FLOAT_EQ(z[2 * 4 + 1], 4.0f);   // d = 0.5 at x = 0, y = 1: row 2, column 1
    EXPECT_EQ(z[1 * 4 + 2], kInf);         // d = 1 at x = 1, y = 0 -> background
    EXPECT_FLOAT_EQ(z[2 * 4 + 2], 3.0f);   // d = 0.25
    EXPECT_EQ(v[2 * 4 + 2], 4.f);
    EXPECT_THAT(a->metadata().attributes.at("depth.convention"), HasSubstr("near 2 far 6"));
    const auto b = readComposableRows(cdb, cdb.query("object = 'b'"), &warnings);
    EXPECT_EQ(b->requireFloat("Z")[2 * 4 + 1], kInf);
    EXPECT_EQ(b->requireFloat("Z")[5], 7.5f);
    EXPECT_THAT(b->metadata().attributes.at("depth.convention"), HasSubstr("Ascent"));
    // Rows of both layers: an error that lists how to pick one.
    try {
        readComposableRows(cdb, cdb.query("CISChannel = 'CISDepth'"));
        ADD_FAILURE() << "two layers were merged";
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("spans 2 layers"));
        EXPECT_THAT(e.what(), HasSubstr("CISImage=i0, CISLayer=lb"));
    }
}

TEST(ComposableImageSet, ProductOfTheWrongSizeIsAnErrorNamingIt) {
    test::TempDir dir;
    std::filesystem::create_directories(dir.file("s.cdb"));
    const std::string db = dir.file("s.cdb");
    writeNpz(db + "/d.npz", {NpyArray{"data", "<f4", {2, 3}, false, std::vector<float>(6, 0.5f)}});
    test::writeText(db + "/data.csv",
                    "CISImage,CISImageWidth,CISImageHeight,CISLayer,CISChannel,FILE\ni,4,4,l,CISDepth,d.npz\n");
    const auto cdb = CinemaDatabase::open(db);
    try {
        readComposableRows(cdb, {0});
        ADD_FAILURE() << "a 2 x 3 product was read as a 4 x 4 layer";
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("d.npz:data.npy: shape (2, 3)"));
        EXPECT_THAT(e.what(), HasSubstr("data.csv:2 CISImageWidth/CISImageHeight"));
        EXPECT_THAT(e.what(), HasSubstr("expected shape (4, 4)"));
    }
}
