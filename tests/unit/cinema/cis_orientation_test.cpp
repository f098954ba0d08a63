// Composable image sets by the CIS convention: channel arrays indexed [x][y]
// (shape = width, height), y counted from the CISOrigin corner (UL assumed
// when absent), layer offsets likewise; C and Fortran order; and every way a
// channel file can disagree with data.csv reported with file, column and
// expectation. Small sets are written here with known values v(x, y).
#include "test_support.h"

#include <darkroom/error.h>
#include <darkroom/data/cinema/composable.h>
#include <darkroom/data/formats/npy.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

using namespace darkroom;
using ::testing::HasSubstr;

namespace {

float valueAt(int x, int y) { return float(10 * x + y + 1); }

// An [x][y] array of w x h values v(x, y), in C order of shape (w, h).
NpyArray xyArray(int w, int h, bool fortran, const std::string& name = "data") {
    NpyArray a{name, "<f4", {std::size_t(w), std::size_t(h)}, fortran, {}};
    for (int x = 0; x < w; ++x)
        for (int y = 0; y < h; ++y) a.values.push_back(valueAt(x, y));
    return a;
}

// One image (W x H) with one layer (w x h at offsetX, offsetY) of one channel.
std::string writeSet(const test::TempDir& dir, int W, int H, int w, int h, int ox, int oy, const std::string& origin,
                     const std::vector<NpyArray>& members, const std::string& extraColumn = "",
                     const std::string& extraValue = "") {
    const std::string db = dir.file("s.cdb");
    std::filesystem::create_directories(db);
    writeNpz(db + "/v.npz", members);
    std::string header = "CISImage,CISImageWidth,CISImageHeight,CISLayer,CISLayerWidth,CISLayerHeight,"
                         "CISLayerOffsetX,CISLayerOffsetY,CISChannel,FILE";
    std::string row = "i0," + std::to_string(W) + "," + std::to_string(H) + ",l0," + std::to_string(w) + "," +
                      std::to_string(h) + "," + std::to_string(ox) + "," + std::to_string(oy) + ",value,v.npz";
    if (!origin.empty()) header += ",CISOrigin", row += "," + origin;
    if (!extraColumn.empty()) header += "," + extraColumn, row += "," + extraValue;
    test::writeText(db + "/data.csv", header + "\n" + row + "\n");
    return db;
}

std::string errorOf(const std::string& db, Diagnostics* warnings = nullptr) {
    try {
        const auto cdb = CinemaDatabase::open(db);
        readComposableRows(cdb, {0}, warnings);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

}  // namespace

// Every origin, both storage orders, a non-square layer at an offset in a
// non-square image: pixel (x, y) of the layer lands where the origin says.
TEST(CisOrientation, XYArraysFollowTheOriginAndOffsetsInCAndFortranOrder) {
    const int W = 7, H = 4, w = 3, h = 2, ox = 1, oy = 2;
    for (const std::string origin : {"", "UL", "ul", "LL", "UR", "LR"}) {
        for (bool fortran : {false, true}) {
            SCOPED_TRACE("origin '" + origin + "' fortran " + std::to_string(fortran));
            test::TempDir dir;
            const auto db = CinemaDatabase::open(writeSet(dir, W, H, w, h, ox, oy, origin, {xyArray(w, h, fortran)}));
            const auto b = readComposableRows(db, {0});
            ASSERT_EQ(b->width(), W);
            ASSERT_EQ(b->height(), H);
            const float* v = b->requireFloat("value");
            const bool fromBottom = origin == "LL" || origin == "LR";
            const bool fromRight = origin == "UR" || origin == "LR";
            int inside = 0;
            for (int x = 0; x < w; ++x)
                for (int y = 0; y < h; ++y) {
                    const int col = fromRight ? W - 1 - (ox + x) : ox + x;
                    const int row = fromBottom ? H - 1 - (oy + y) : oy + y;
                    EXPECT_EQ(v[row * W + col], valueAt(x, y)) << "x " << x << " y " << y;
                }
            for (int i = 0; i < W * H; ++i) inside += !std::isnan(v[i]);
            EXPECT_EQ(inside, w * h) << "pixels outside the layer stay NaN";
            const std::string o = b->metadata().attributes.at("cis.origin");
            if (origin.empty()) EXPECT_EQ(o, "UL (assumed: no CISOrigin in data.csv)");
            else EXPECT_EQ(o, origin == "ul" ? "UL" : origin);
        }
    }
}

// ParaView's recolorable-image extracts: an .npy of shape (700, 400) for a 700 x 400 image.
TEST(CisOrientation, ShapeWidthHeightIsAWideImage) {
    test::TempDir dir;
    const auto db = CinemaDatabase::open(writeSet(dir, 700, 400, 700, 400, 0, 0, "", {xyArray(700, 400, false)}));
    const auto b = readComposableRows(db, {0});
    EXPECT_EQ(b->width(), 700);
    EXPECT_EQ(b->height(), 400);
    EXPECT_EQ(b->requireFloat("value")[399 * 700 + 699], valueAt(699, 399));
}

TEST(CisOrientation, RowsFirstArrayIsAnErrorThatSaysSo) {
    test::TempDir dir;
    NpyArray rowsFirst{"data", "<f4", {400, 700}, false, std::vector<float>(400 * 700, 0.5f)};
    const std::string e = errorOf(writeSet(dir, 700, 400, 700, 400, 0, 0, "", {rowsFirst}));
    EXPECT_THAT(e, HasSubstr("v.npz:data.npy: shape (400, 700)"));
    EXPECT_THAT(e, HasSubstr("data.csv:2 CISLayerWidth/CISLayerHeight say layer l0 is 700 x 400"));
    EXPECT_THAT(e, HasSubstr("expected shape (700, 400)"));
    EXPECT_THAT(e, HasSubstr("(height, width), rows first"));
}

TEST(CisOrientation, UnknownOriginIsAnErrorNamingTheColumn) {
    test::TempDir dir;
    const std::string e = errorOf(writeSet(dir, 2, 2, 2, 2, 0, 0, "top", {xyArray(2, 2, false)}));
    EXPECT_THAT(e, HasSubstr("data.csv:2: CISOrigin is 'top'; expected UL, UR, LL or LR"));
}

TEST(CisVariants, MembersOtherThanDataAreReportedOrRefused) {
    {
        test::TempDir dir;
        Diagnostics warnings;
        const auto db = CinemaDatabase::open(writeSet(dir, 3, 2, 3, 2, 0, 0, "", {xyArray(3, 2, false, "values")}));
        const auto b = readComposableRows(db, {0}, &warnings);
        EXPECT_EQ(b->requireFloat("value")[1 * 3 + 2], valueAt(2, 1));
        ASSERT_EQ(warnings.size(), 1u);
        EXPECT_THAT(warnings[0].where, HasSubstr("v.npz"));
        EXPECT_THAT(warnings[0].message, HasSubstr("only member is 'values.npy', not 'data.npy'"));
    }
    {
        test::TempDir dir;
        const std::string e =
            errorOf(writeSet(dir, 3, 2, 3, 2, 0, 0, "", {xyArray(3, 2, false, "a"), xyArray(3, 2, false, "b")}));
        EXPECT_THAT(e, HasSubstr("v.npz: no member 'data.npy' holds channel value ("));
        EXPECT_THAT(e, HasSubstr("data.csv:2 CISChannel value); expected one member named 'data', found 'a.npy', 'b.npy'"));
    }
}

TEST(CisVariants, DtypeThatContradictsCisChannelVarTypeIsAnError) {
    test::TempDir dir;
    const std::string e =
        errorOf(writeSet(dir, 3, 2, 3, 2, 0, 0, "", {xyArray(3, 2, false)}, "CISChannelVarType", "int"));
    EXPECT_THAT(e, HasSubstr("v.npz:data.npy: dtype '<f4', but"));
    EXPECT_THAT(e, HasSubstr("data.csv:2 CISChannelVarType says 'int' (expected an integer dtype"));
    test::TempDir ok;
    const auto db = CinemaDatabase::open(
        writeSet(ok, 3, 2, 3, 2, 0, 0, "", {xyArray(3, 2, false)}, "CISChannelVarType", "float"));
    EXPECT_NO_THROW(readComposableRows(db, {0}));
}

TEST(CisVariants, RowsOfOneLayerThatDisagreeOnItsSizeAreAnError) {
    test::TempDir dir;
    const std::string db = dir.file("s.cdb");
    std::filesystem::create_directories(db);
    writeNpz(db + "/a.npz", {xyArray(2, 2, false)});
    writeNpz(db + "/b.npz", {xyArray(2, 2, false)});
    test::writeText(db + "/data.csv",
                    "CISImage,CISImageWidth,CISImageHeight,CISLayer,CISLayerWidth,CISLayerHeight,CISChannel,FILE\n"
                    "i,4,4,l,2,2,CISDepth,a.npz\n"
                    "i,4,4,l,2,3,value,b.npz\n");
    const auto cdb = CinemaDatabase::open(db);
    try {
        composableImages(cdb);
        ADD_FAILURE() << "the second row's layer height was ignored";
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("data.csv:3: CISLayerHeight is 3 but earlier rows of layer l of image i say 2"));
    }
}
