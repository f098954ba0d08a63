// `darkroom info` names every product that disagrees with data.csv and exits
// with 2 (bad input) when one cannot be read as data.csv says; the shared
// databases written by others pass.
#include "runner_process.h"
#include "test_support.h"

#include <darkroom/data/formats/npy.h>

#include <gtest/gtest.h>

#include <filesystem>

using namespace darkroom;
using darkroom::test::runDarkroom;

TEST(InfoConsistency, DisagreeingChannelFileFailsWithFileColumnAndExpectation) {
    test::TempDir dir;
    const std::string db = dir.file("c.cdb");
    std::filesystem::create_directories(db);
    writeNpz(db + "/z.npz", {NpyArray{"data", "<f4", {4, 2}, false, std::vector<float>(8, 0.5f)}});
    writeNpz(db + "/v.npz", {NpyArray{"data", "<f4", {2, 4}, false, std::vector<float>(8, 0.5f)}});
    test::writeText(db + "/data.csv",
                    "CISImage,CISImageWidth,CISImageHeight,CISLayer,CISChannel,FILE\n"
                    "i,4,2,l,CISDepth,z.npz\ni,4,2,l,value,v.npz\ni,4,2,l,other,gone.npz\n");
    const auto r = runDarkroom({"info", db});
    EXPECT_EQ(r.exitCode, 2) << r.out << r.err;
    const std::string all = r.out + r.err;
    EXPECT_NE(all.find("v.npz:data.npy: shape (2, 4), but " + db + "/data.csv:3 CISImageWidth/CISImageHeight"),
              std::string::npos)
        << all;
    EXPECT_NE(all.find("data.csv:4: error: FILE names 'gone.npz', which does not exist"), std::string::npos) << all;
}

TEST(InfoConsistency, SharedDatabasesPass) {
    for (const char* name : {"sphere.cdb", "multiple_artifacts.cdb", "periodicPicture.cdb", "ttk_extracts_001.cdb"}) {
        const std::string path = test::sharedData(std::string("cinema/") + name);
        if (path.empty()) GTEST_SKIP() << "../shared/data/cinema is absent";
        const auto r = runDarkroom({"info", path});
        EXPECT_EQ(r.exitCode, 0) << name << "\n" << r.out << r.err;
    }
}
