// checkProductFiles: every product of a database against data.csv, each
// disagreement named by file, data.csv line, column and expectation.
#include "test_support.h"

#include <darkroom/data/cinema/consistency.h>
#include <darkroom/data/formats/npy.h>
#include <darkroom/data/image_io.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

using namespace darkroom;
using ::testing::HasSubstr;

namespace {

std::string all(const Diagnostics& d) {
    std::string s;
    for (const auto& x : d) s += x.str() + "\n";
    return s;
}

std::size_t errors(const Diagnostics& d) {
    std::size_t n = 0;
    for (const auto& x : d) n += x.severity == Diagnostic::Severity::Error;
    return n;
}

}  // namespace

TEST(ProductConsistency, SpecDMissingFilesOtherSizesAndChannelsAreNamed) {
    test::TempDir dir;
    const std::string db = dir.file("d.cdb");
    std::filesystem::create_directories(db + "/img");
    writeImage(*test::makeImage(4, 3, {"R", "G", "B"}, [](int, int, int) { return 0.5f; }), db + "/img/a.png");
    writeImage(*test::makeImage(4, 3, {"R", "G", "B"}, [](int, int, int) { return 0.2f; }), db + "/img/b.png");
    writeImage(*test::makeImage(5, 3, {"R", "G", "B"}, [](int, int, int) { return 0.2f; }), db + "/img/c.png");
    writeImage(*test::makeImage(4, 3, {"R", "G", "B", "A"}, [](int, int, int) { return 1.f; }), db + "/img/d.png");
    test::writeText(db + "/data.csv",
                    "phi,FILE\n0,img/a.png\n10,img/b.png\n20,img/c.png\n30,img/gone.png\n40,img/d.png\n");
    const Diagnostics d = checkProductFiles(CinemaDatabase::open(db));
    EXPECT_EQ(errors(d), 1u) << all(d);
    EXPECT_EQ(d.size(), 3u) << all(d);
    EXPECT_THAT(all(d), HasSubstr("data.csv:5: error: FILE names 'img/gone.png', which does not exist"));
    EXPECT_THAT(all(d), HasSubstr("img/c.png: warning: 5 x 3 pixels, but the first product of column FILE ("));
    EXPECT_THAT(all(d), HasSubstr("a.png, " + db + "/data.csv:2) is 4 x 3"));
    EXPECT_THAT(all(d), HasSubstr("img/d.png: warning: channels R, G, B, A, but the first product of column FILE"));
}

TEST(ProductConsistency, ComposableShapesAndTypesAreCheckedFromHeaders) {
    test::TempDir dir;
    const std::string db = dir.file("c.cdb");
    std::filesystem::create_directories(db);
    writeNpz(db + "/z.npz", {NpyArray{"data", "<f4", {3, 2}, false, std::vector<float>(6, 0.5f)}});
    writeNpz(db + "/v.npz", {NpyArray{"data", "<f4", {2, 3}, false, std::vector<float>(6, 0.5f)}});
    test::writeText(db + "/data.csv",
                    "CISImage,CISImageWidth,CISImageHeight,CISLayer,CISChannel,CISChannelVarType,FILE\n"
                    "i,3,2,l,CISDepth,float,z.npz\n"
                    "i,3,2,l,value,float,v.npz\n");
    const Diagnostics d = checkProductFiles(CinemaDatabase::open(db));
    ASSERT_EQ(d.size(), 1u) << all(d);
    EXPECT_THAT(d[0].message, HasSubstr("v.npz:data.npy: shape (2, 3), but " + db + "/data.csv:3 "
                                        "CISImageWidth/CISImageHeight (the layer's size by default) say layer l is "
                                        "3 x 2 (expected shape (3, 2)"));
}

TEST(ProductConsistency, SharedDatabasesAgreeWithTheirDataCsv) {
    for (const char* name : {"sphere.cdb", "multiple_artifacts.cdb", "periodicPicture.cdb", "ttk_extracts_001.cdb"}) {
        const std::string path = test::sharedData(std::string("cinema/") + name);
        if (path.empty()) GTEST_SKIP() << "../shared/data/cinema is absent";
        const Diagnostics d = checkProductFiles(CinemaDatabase::open(path));
        EXPECT_TRUE(d.empty()) << name << ":\n" << all(d);
    }
}
