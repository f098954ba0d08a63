// Layered captures end to end (issue 30): `channels: {layers: K}` in a scene
// file, `darkroom capture` storing the K nearest crossings per pixel,
// `darkroom info` reporting them, and a CinemaReader -> CinemaWriter run
// giving a database with the same channels and values. Three parallel
// planes at known depths give the answers.
#include "runner_process.h"
#include "test_support.h"

#include <darkroom/data/cinema/product.h>
#include <darkroom/layers.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>

namespace fs = std::filesystem;
using namespace darkroom;
using darkroom::test::runDarkroom;

namespace {

// Planes facing the camera at z = 0, -1, -2.5, seen from z = 5.
std::string scene(const std::string& layers) {
    std::string s = "objects:\n";
    for (const char* z : {"0", "-1", "-2.5"})
        s += std::string("  - generator: plane\n    parameters: {size: 4, center: [0, 0, ") + z + "]}\n";
    return s + R"(cameras:
  projection: orthographic
  height: 2
  resolution: [16, 12]
  list:
    - {position: [0, 0, 5], target: [0, 0, 0], up: [0, 1, 0]}
channels:
  normals: true
  objectId: true
  layers: )" + layers + "\n";
}

// The one product of a database.
std::string product(const std::string& cdb) {
    for (const auto& f : fs::directory_iterator(cdb))
        if (f.path().extension() == ".exr") return f.path().string();
    return {};
}

BufferPtr captured(const test::TempDir& dir, const std::string& name, const std::string& layers) {
    test::writeText(dir.file(name + ".yaml"), scene(layers));
    const auto cap = runDarkroom({"-q", "capture", dir.file(name + ".yaml"), "--output", dir.file(name + ".cdb")});
    EXPECT_EQ(cap.exitCode, 0) << cap.err;
    return readCinemaProduct(product(dir.file(name + ".cdb")));
}

bool sameChannel(const Buffer& a, const Buffer& b, const std::string& n) {
    const bool ids = a.channelType(n) == ChannelType::UInt32;
    const void* pa = ids ? static_cast<const void*>(a.hostUInt(n)) : a.hostFloat(n);
    const void* pb = ids ? static_cast<const void*>(b.hostUInt(n)) : b.hostFloat(n);
    return pa && pb && std::memcmp(pa, pb, 4 * a.pixelCount()) == 0;
}

}  // namespace

TEST(LayersCli, CaptureStoresTheCrossingsFrontToBackAndInfoReportsThem) {
    test::TempDir dir;
    const BufferPtr g = captured(dir, "four", "4");
    ASSERT_EQ(layers::count(*g), 4);
    const float inf = std::numeric_limits<float>::infinity();
    for (std::size_t i = 0; i < g->pixelCount(); ++i) {
        ASSERT_FLOAT_EQ(g->hostFloat("Z")[i], 5.0f);
        ASSERT_FLOAT_EQ(g->hostFloat("layer1.Z")[i], 6.0f);
        ASSERT_FLOAT_EQ(g->hostFloat("layer2.Z")[i], 7.5f);
        ASSERT_EQ(g->hostFloat("layer3.Z")[i], inf);
        ASSERT_EQ(g->hostUInt("layer2.objectId")[i], 2u);
        ASSERT_EQ(g->hostUInt("layer3.objectId")[i], 0xFFFFFFFFu);
        ASSERT_TRUE(std::isnan(g->hostFloat("layer3.N.z")[i]));
    }
    const auto info = runDarkroom({"info", dir.file("four.cdb")});
    ASSERT_EQ(info.exitCode, 0) << info.err;
    EXPECT_NE(info.out.find("layers   4 (Z, height, N, objectId per layer"), std::string::npos) << info.out;
    EXPECT_NE(info.out.find("layer3.Z (float32)"), std::string::npos) << info.out;

    // Layer 0 is the one-layer capture, byte for byte.
    const BufferPtr one = captured(dir, "one", "1");
    for (const auto& ch : one->channels()) EXPECT_TRUE(sameChannel(*one, *g, ch.name)) << ch.name;
    const auto infoOne = runDarkroom({"info", dir.file("one.cdb")});
    EXPECT_EQ(infoOne.out.find("layers"), std::string::npos) << infoOne.out;
}

TEST(LayersCli, ALayeredDatabaseRoundTripsThroughCinemaReaderAndWriter) {
    test::TempDir dir;
    const BufferPtr g = captured(dir, "layered", "3");
    test::writeText(dir.file("copy.yaml"), "darkroom: 1\nnodes:\n  read: {type: CinemaReader, parameters: {database: " +
                                               dir.file("layered.cdb") +
                                               "}}\n  store: {type: CinemaWriter, parameters: {database: " +
                                               dir.file("copy.cdb") + ", format: exr}}\nedges:\n"
                                               "  - read.image -> store.image\n  - read.row -> store.row\n");
    const auto run = runDarkroom({"-q", "run", dir.file("copy.yaml"), "--foreach", "read"});
    ASSERT_EQ(run.exitCode, 0) << run.err << run.out;
    const BufferPtr copy = readCinemaProduct(product(dir.file("copy.cdb")));
    ASSERT_EQ(copy->channelNames(), g->channelNames());
    for (const auto& ch : g->channels()) EXPECT_TRUE(sameChannel(*g, *copy, ch.name)) << ch.name;
}

TEST(LayersCli, ALayerCountOutOfRangeNamesTheSceneLine) {
    test::TempDir dir;
    test::writeText(dir.file("bad.yaml"), scene("17"));
    const auto cap = runDarkroom({"capture", dir.file("bad.yaml"), "--output", dir.file("bad.cdb")});
    EXPECT_NE(cap.exitCode, 0);
    EXPECT_NE(cap.err.find("bad.yaml:17"), std::string::npos) << cap.err;
    EXPECT_NE(cap.err.find("layers (surface crossings per pixel) must be an integer from 1 to 16"), std::string::npos)
        << cap.err;
}
