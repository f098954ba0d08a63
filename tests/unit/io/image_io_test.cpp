// readImage / writeImage: EXR exactness, 8-bit sRGB quantisation, errors.
#include "test_support.h"

#include <darkroom/error.h>
#include <darkroom/data/image_io.h>
#include <darkroom/srgb.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>

using namespace darkroom;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

namespace {

// Every float class that must survive: NaN with a payload, infinities, -0,
// denormals, the extremes, values that need all 24 mantissa bits.
std::shared_ptr<WritableBuffer> awkwardImage() {
    auto b = makeCpuBuffer(7, 5, {{"Z", ChannelType::Float32},
                                  {"Elevation", ChannelType::Float32},
                                  {"objectId", ChannelType::UInt32},
                                  {"Normal.X", ChannelType::Float32}});
    const float specials[] = {std::bit_cast<float>(0x7fc01234u), std::numeric_limits<float>::infinity(),
                              -std::numeric_limits<float>::infinity(), -0.0f,
                              std::numeric_limits<float>::denorm_min(), std::numeric_limits<float>::max(),
                              std::numeric_limits<float>::lowest(), 16777217.0f, 0.1f, 1.0f / 3.0f};
    for (std::size_t i = 0; i < b->pixelCount(); ++i) {
        b->writeFloat("Z")[i] = i % 3 == 0 ? std::numeric_limits<float>::infinity() : 1.0f + float(i) / 7.0f;
        b->writeFloat("Elevation")[i] = specials[i % std::size(specials)];
        b->writeUInt("objectId")[i] = i == 0 ? 0xffffffffu : std::uint32_t(i * 2654435761u);
        b->writeFloat("Normal.X")[i] = std::sin(float(i));
    }
    Camera c;
    c.position = {0.1, 1.0 / 3.0, -7.25e10};
    c.forward = {0.2, -0.9, std::nextafter(0.3, 1.0)};
    c.up = {0, 0, 1};
    c.projection = Camera::Projection::Orthographic;
    c.fovYDegrees = 33.333333333333336;
    c.viewHeight = 12.5;
    c.width = 7;
    c.height = 5;
    b->metadata().camera = c;
    b->metadata().attributes["units.Z"] = "m";
    b->metadata().attributes["provenance"] = "capture, \"quoted\", ünïcode";
    return b;
}

std::shared_ptr<WritableBuffer> rgbaRamp(int w) {
    return test::makeImage(w, 2, {"R", "G", "B", "A"}, [w](int x, int y, int c) {
        const float t = float(x) / float(w - 1);
        if (c == 3) return y == 0 ? t : 1.0f - t;
        return c == 0 ? t : c == 1 ? t * t : 1.0f - t;
    });
}

void expectNoTemporaries(const std::string& dir) {
    for (const auto& e : fs::directory_iterator(dir))
        EXPECT_EQ(e.path().filename().string().find(".tmp-"), std::string::npos) << e.path();
}

}  // namespace

TEST(ImageIo, ExrRoundTripIsBitExactWithCameraAttributesAndChannelOrder) {
    test::TempDir dir;
    const auto b = awkwardImage();
    writeImage(*b, dir.file("gbuffer.exr"));
    const auto r = readImage(dir.file("gbuffer.exr"));
    // Same channels in the same order (EXR itself sorts them), same types,
    // same bits (NaN payload included), equal camera and attributes.
    EXPECT_EQ(r->channelNames(), b->channelNames());
    EXPECT_EQ(r->channelType("objectId"), ChannelType::UInt32);
    EXPECT_EQ(r->hostUInt("objectId")[0], 0xffffffffu);
    EXPECT_EQ(std::bit_cast<std::uint32_t>(r->hostFloat("Elevation")[0]), 0x7fc01234u);
    ASSERT_TRUE(r->metadata().camera.has_value());
    EXPECT_EQ(*r->metadata().camera, *b->metadata().camera);
    EXPECT_EQ(r->metadata().attributes, b->metadata().attributes);
    EXPECT_TRUE(identical(*b, *r));
    expectNoTemporaries(dir.path());
}

TEST(ImageIo, AttributesOfTheRunAreNotStored) {
    // "run.*" describes the run (the rows a --foreach --where covers), not
    // the picture: a file must not differ with the run that wrote it.
    test::TempDir dir;
    auto b = awkwardImage();
    const auto kept = b->metadata().attributes;
    b->metadata().attributes["run.selection"] = "theta=40";
    writeImage(*b, dir.file("entry.exr"));
    EXPECT_EQ(readImage(dir.file("entry.exr"))->metadata().attributes, kept);
}

TEST(ImageIo, EveryLosslessCompressionRoundTripsExactly) {
    test::TempDir dir;
    const auto b = awkwardImage();
    for (const char* c : {"none", "rle", "zips", "zip", "piz"}) {
        ImageWriteOptions o;
        o.compression = c;
        writeImage(*b, dir.file(std::string(c) + ".exr"), o);
        EXPECT_TRUE(identical(*b, *readImage(dir.file(std::string(c) + ".exr")))) << c;
    }
}

TEST(ImageIo, HalfKeepsDepthAndIdsExactAndRoundsTheRest) {
    test::TempDir dir;
    const auto b = awkwardImage();
    ImageWriteOptions o;
    o.halfFloat = true;
    writeImage(*b, dir.file("half.exr"), o);
    const auto r = readImage(dir.file("half.exr"));
    EXPECT_EQ(r->channelType("objectId"), ChannelType::UInt32);
    EXPECT_EQ(r->channelType("Normal.X"), ChannelType::Float32);  // widened on read
    for (std::size_t i = 0; i < b->pixelCount(); ++i) {
        EXPECT_EQ(r->hostFloat("Z")[i], b->hostFloat("Z")[i]);
        EXPECT_EQ(r->hostUInt("objectId")[i], b->hostUInt("objectId")[i]);
        const float n = b->hostFloat("Normal.X")[i];
        EXPECT_NEAR(r->hostFloat("Normal.X")[i], n, std::abs(n) / 1024.0f + 1e-7f);
    }
}

TEST(ImageIo, ExrChannelSubset) {
    test::TempDir dir;
    ImageWriteOptions o;
    o.channels = {"objectId", "Z"};
    writeImage(*awkwardImage(), dir.file("sub.exr"), o);
    EXPECT_EQ(readImage(dir.file("sub.exr"))->channelNames(), (std::vector<std::string>{"objectId", "Z"}));
}

TEST(ImageIo, PngIsSrgbEncodedWithinOneQuantisationStep) {
    test::TempDir dir;
    const int w = 1024;
    const auto b = rgbaRamp(w);
    writeImage(*b, dir.file("ramp.png"));
    const auto r = readImage(dir.file("ramp.png"));
    EXPECT_EQ(r->channelNames(), (std::vector<std::string>{"R", "G", "B", "A"}));
    const float step = 0.5f / 255.0f + 1e-6f;
    for (std::size_t i = 0; i < b->pixelCount(); ++i) {
        for (const char* c : {"R", "G", "B"})
            ASSERT_NEAR(linearToSrgb(r->hostFloat(c)[i]), linearToSrgb(b->hostFloat(c)[i]), step) << c << i;
        ASSERT_NEAR(r->hostFloat("A")[i], b->hostFloat("A")[i], step) << "alpha is stored linearly, straight";
    }
    // Linear 0.5 is sRGB code 188, not 128.
    const auto half = test::makeImage(1, 1, {"Y"}, [](int, int, int) { return 0.5f; });
    writeImage(*half, dir.file("half.png"));
    EXPECT_NEAR(readImage(dir.file("half.png"))->hostFloat("Y")[0], srgbToLinear(188.0f / 255.0f), 1e-6f);
}

TEST(ImageIo, EightBitClampsAndWritesNanAsZero) {
    test::TempDir dir;
    const float values[] = {std::numeric_limits<float>::quiet_NaN(), -3.0f, 7.0f,
                            std::numeric_limits<float>::infinity()};
    const auto b = test::makeImage(4, 1, {"R", "G", "B"}, [&](int x, int, int) { return values[x]; });
    for (const char* name : {"c.png", "c.tif"}) {
        writeImage(*b, dir.file(name));
        const auto r = readImage(dir.file(name));
        EXPECT_EQ(r->hostFloat("R")[0], 0.0f) << name;
        EXPECT_EQ(r->hostFloat("G")[1], 0.0f) << name;
        EXPECT_EQ(r->hostFloat("B")[2], 1.0f) << name;
        EXPECT_EQ(r->hostFloat("R")[3], 1.0f) << name;
    }
}

TEST(ImageIo, GreyAndChosenChannelsAndJpeg) {
    test::TempDir dir;
    const auto b = test::makeImage(16, 16, {"Z", "Elevation"}, [](int x, int y, int c) {
        return c == 0 ? 1.0f : float(x + y) / 30.0f;
    });
    // The one float channel besides Z becomes grey.
    writeImage(*b, dir.file("grey.png"));
    const auto g = readImage(dir.file("grey.png"));
    EXPECT_EQ(g->channelNames(), std::vector<std::string>{"Y"});
    EXPECT_NEAR(g->hostFloat("Y")[17], b->hostFloat("Elevation")[17], 0.01f);

    const auto c = rgbaRamp(64);
    writeImage(*c, dir.file("ramp.jpg"));  // JPEG has no alpha
    const auto j = readImage(dir.file("ramp.jpg"));
    EXPECT_EQ(j->channelNames(), (std::vector<std::string>{"R", "G", "B"}));
    EXPECT_NEAR(j->hostFloat("R")[40], c->hostFloat("R")[40], 0.05f);

    ImageWriteOptions o;
    o.channels = {"B", "G", "R"};
    writeImage(*c, dir.file("swapped.png"), o);
    EXPECT_EQ(readImage(dir.file("swapped.png"))->hostFloat("R")[0], 1.0f);  // B was 1 at x = 0
}

TEST(ImageIo, OverwritesAtomically) {
    test::TempDir dir;
    writeImage(*rgbaRamp(8), dir.file("a.exr"));
    const auto second = awkwardImage();
    writeImage(*second, dir.file("a.exr"));
    EXPECT_TRUE(identical(*second, *readImage(dir.file("a.exr"))));
    expectNoTemporaries(dir.path());
}

TEST(ImageIo, MissingFileNamesTheFile) {
    test::TempDir dir;
    const std::string path = dir.file("nothing-here.exr");
    try {
        readImage(path);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr(path));
        EXPECT_THAT(e.what(), HasSubstr("no such file"));
    }
}

TEST(ImageIo, TruncatedPngNamesTheFile) {
    test::TempDir dir;
    // Noise does not compress, so cutting the file loses pixel data.
    std::uint32_t s = 1;
    const auto noise = test::makeImage(128, 128, {"R", "G", "B"}, [&](int, int, int) {
        s = s * 1664525u + 1013904223u;
        return float(s >> 8) / 16777216.0f;
    });
    writeImage(*noise, dir.file("noise.png"));
    const std::string bytes = test::readText(dir.file("noise.png"));
    for (std::size_t keep : {std::size_t(100), bytes.size() / 2}) {
        const std::string path = dir.file("cut" + std::to_string(keep) + ".png");
        test::writeText(path, bytes.substr(0, keep));
        try {
            readImage(path);
            FAIL() << "no error for " << keep << " bytes";
        } catch (const Error& e) {
            EXPECT_THAT(e.what(), HasSubstr(path));
            EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "one line";
        }
    }
}

TEST(ImageIo, TextFileNamedExrNamesTheFile) {
    test::TempDir dir;
    const std::string path = dir.file("notes.exr");
    test::writeText(path, "this is not an image\n");
    try {
        readImage(path);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr(path));
    }
}

TEST(ImageIo, WriteErrorsNameTheFile) {
    test::TempDir dir;
    const auto b = awkwardImage();
    auto expectError = [&](const std::string& path, const ImageWriteOptions& o, const std::string& why) {
        try {
            writeImage(*b, path, o);
            FAIL() << "no error for " << path;
        } catch (const Error& e) {
            EXPECT_THAT(e.what(), HasSubstr(path));
            EXPECT_THAT(e.what(), HasSubstr(why));
        }
    };
    expectError(dir.file("x.unknownformat"), {}, "no image format");
    expectError(dir.file("missing/folder/x.exr"), {}, "does not exist");
    ImageWriteOptions badCompression;
    badCompression.compression = "lzma";
    expectError(dir.file("x.exr"), badCompression, "lzma");
    ImageWriteOptions ids;
    ids.channels = {"objectId"};
    expectError(dir.file("ids.png"), ids, "objectId");
    ImageWriteOptions absent;
    absent.channels = {"Nope"};
    expectError(dir.file("absent.exr"), absent, "Nope");
    // Two float channels besides Z: which one is grey is ambiguous.
    expectError(dir.file("ambiguous.png"), {}, "Elevation");
    expectNoTemporaries(dir.path());
    EXPECT_FALSE(fs::exists(dir.file("x.exr")));
}
