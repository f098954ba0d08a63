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

namespace {

// A VTK ImageData volume of 2 x 2 x 2 points (what a simulation writes, not
// an image).
void writeVolumeVti(const std::string& path) {
    test::writeText(path, R"(<?xml version="1.0"?>
<VTKFile type="ImageData" version="1.0" byte_order="LittleEndian" header_type="UInt64">
  <ImageData WholeExtent="0 1 0 1 0 1" Origin="0 0 0" Spacing="1 1 1">
    <Piece Extent="0 1 0 1 0 1">
      <PointData>
        <DataArray type="Float64" Name="d" format="ascii">0 1 0 1 0 1 0 1</DataArray>
      </PointData>
    </Piece>
  </ImageData>
</VTKFile>
)");
}

}  // namespace

// Issue 29 item 7: a database of volumes is described as such, pointing to
// `darkroom capture` (volumes become G-buffers through a scene's volume
// object), not as an unreadable image; reading an entry says the same.
TEST(InfoConsistency, VolumeProductsPointToCapture) {
    test::TempDir dir;
    const std::string db = dir.file("vol.cdb");
    std::filesystem::create_directories(db);
    for (const char* t : {"0", "1"}) writeVolumeVti(db + "/t" + t + ".vti");
    test::writeText(db + "/data.csv", "time,FILE\n0,t0.vti\n1,t1.vti\n");
    const auto r = runDarkroom({"info", db});
    EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("not images: " + db + "/t0.vti is a volume (VTK ImageData of 2 x 2 x 2 points)"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("capture it into G-buffers with `darkroom capture SCENE -o DB.cdb`, SCENE naming it as an "
                         "object (objects: [{file: " + db + "/t0.vti}]"),
              std::string::npos)
        << r.out;
    EXPECT_EQ(r.out.find("could not read"), std::string::npos) << r.out;

    // A legacy .vtk volume: capture does not read those, so convert first.
    test::writeText(db + "/t2.vtk", "# vtk DataFile Version 3.0\nvolume\nASCII\nDATASET STRUCTURED_POINTS\n"
                                    "DIMENSIONS 2 2 2\nORIGIN 0 0 0\nSPACING 1 1 1\n");
    test::writeText(db + "/data.csv", "time,FILE\n2,t2.vtk\n");
    const auto legacy = runDarkroom({"info", db});
    EXPECT_EQ(legacy.exitCode, 0) << legacy.out << legacy.err;
    EXPECT_NE(legacy.out.find("t2.vtk is VTK legacy STRUCTURED_POINTS data (a grid or volume)"), std::string::npos)
        << legacy.out;
    EXPECT_NE(legacy.out.find("convert it (ParaView, meshio) and capture that"), std::string::npos) << legacy.out;

    // Shading an entry is refused (bad input) with the same advice.
    test::writeText(db + "/data.csv", "time,FILE\n0,t0.vti\n");
    test::writeText(dir.file("p.yaml"), "darkroom: 1\nnodes:\n  read: {type: CinemaReader, parameters: {database: "
                                        "vol.cdb}}\n  write: {type: ImageWriter, parameters: {path: v.exr}}\n"
                                        "edges:\n  - read.image -> write.image\n");
    const auto run = runDarkroom({"-q", "run", dir.file("p.yaml")});
    EXPECT_EQ(run.exitCode, 2) << run.err;
    EXPECT_NE(run.err.find("node 'read' (CinemaReader): " + db + "/t0.vti: a volume (VTK ImageData of 2 x 2 x 2 "
                           "points), not an image. Darkroom shades images: capture it"),
              std::string::npos)
        << run.err;
}
