// EXR and PNG are written and read by the framework itself (OpenEXR, libpng)
// and every other format by the OpenImageIO module. The two must agree: a
// file written by one reads the same through the other, bit for bit, with
// the same channel order, camera and attributes; PNG pixels are identical
// whichever encoder wrote them. And a process that meets only EXR and PNG
// never loads OpenImageIO.
#include "../../../framework/data/oiio/module.h"
#include "test_support.h"

#include <darkroom/error.h>
#include <darkroom/data/image_io.h>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <dlfcn.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>

using namespace darkroom;
using ::testing::HasSubstr;

namespace {

const oiio_module::Entry& oiio() {
    static const oiio_module::Entry* entry = [] {
        void* h = ::dlopen(DARKROOM_OIIO_MODULE, RTLD_NOW | RTLD_LOCAL);
        if (!h) return static_cast<const oiio_module::Entry*>(nullptr);
        auto fn = reinterpret_cast<const oiio_module::Entry* (*)()>(::dlsym(h, oiio_module::kEntrySymbol));
        return fn ? fn() : nullptr;
    }();
    if (!entry) throw Error("cannot open " DARKROOM_OIIO_MODULE);
    return *entry;
}

bool oiioLoaded() {
    std::ifstream maps("/proc/self/maps");
    std::string line;
    while (std::getline(maps, line))
        if (line.find("libOpenImageIO.so") != std::string::npos) return true;
    return false;
}

// Channels deliberately not in alphabetical order, every float class, uint ids.
std::shared_ptr<WritableBuffer> gbuffer() {
    auto b = makeCpuBuffer(9, 4, {{"Z", ChannelType::Float32},
                                  {"pressure", ChannelType::Float32},
                                  {"objectId", ChannelType::UInt32},
                                  {"N.x", ChannelType::Float32},
                                  {"A", ChannelType::Float32}});
    const float specials[] = {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                              -0.0f, std::numeric_limits<float>::denorm_min(), 16777217.0f, 1.0f / 3.0f};
    for (std::size_t i = 0; i < b->pixelCount(); ++i) {
        b->writeFloat("Z")[i] = i % 4 == 0 ? std::numeric_limits<float>::infinity() : 2.0f + float(i) / 9.0f;
        b->writeFloat("pressure")[i] = specials[i % std::size(specials)];
        b->writeUInt("objectId")[i] = std::uint32_t(i * 2654435761u);
        b->writeFloat("N.x")[i] = std::cos(float(i));
        b->writeFloat("A")[i] = float(i % 3) / 2.0f;
    }
    Camera c;
    c.position = {0.1, 1.0 / 3.0, -7.25e10};
    c.forward = {0.0, -1.0, 0.0};
    c.up = {0, 0, 1};
    c.fovYDegrees = 33.333333333333336;
    c.viewHeight = 2.5;
    c.width = 9;
    c.height = 4;
    b->metadata().camera = c;
    b->metadata().attributes["units.Z"] = "m";
    return b;
}

void expectSame(const Buffer& a, const Buffer& b) {
    ASSERT_EQ(a.width(), b.width());
    ASSERT_EQ(a.height(), b.height());
    ASSERT_EQ(a.channels().size(), b.channels().size());
    for (std::size_t c = 0; c < a.channels().size(); ++c) {
        const ChannelDesc& ca = a.channels()[c];
        EXPECT_EQ(ca.name, b.channels()[c].name) << "channel " << c;
        EXPECT_EQ(ca.type, b.channels()[c].type) << ca.name;
        const void* pa = ca.type == ChannelType::UInt32 ? static_cast<const void*>(a.hostUInt(ca.name))
                                                        : static_cast<const void*>(a.hostFloat(ca.name));
        const void* pb = ca.type == ChannelType::UInt32 ? static_cast<const void*>(b.hostUInt(ca.name))
                                                        : static_cast<const void*>(b.hostFloat(ca.name));
        ASSERT_TRUE(pa && pb) << ca.name;
        EXPECT_EQ(0, std::memcmp(pa, pb, a.pixelCount() * 4)) << ca.name << " differs";
    }
    ASSERT_EQ(a.metadata().camera.has_value(), b.metadata().camera.has_value());
    if (a.metadata().camera) {
        const Camera &x = *a.metadata().camera, &y = *b.metadata().camera;
        EXPECT_EQ(x.position.x, y.position.x);
        EXPECT_EQ(x.position.z, y.position.z);
        EXPECT_EQ(x.forward.y, y.forward.y);
        EXPECT_EQ(x.up.z, y.up.z);
        EXPECT_EQ(x.fovYDegrees, y.fovYDegrees);
        EXPECT_EQ(x.viewHeight, y.viewHeight);
        EXPECT_EQ(x.width, y.width);
        EXPECT_EQ(x.projection, y.projection);
    }
    EXPECT_EQ(a.metadata().attributes, b.metadata().attributes);
}

}  // namespace

TEST(NativeVsOiio, ExrWrittenNativelyReadsTheSameThroughOpenImageIO) {
    test::TempDir dir;
    const auto b = gbuffer();
    writeImage(*b, dir.file("g.exr"));
    expectSame(*readImage(dir.file("g.exr")), *oiio().readImage(dir.file("g.exr")));
    expectSame(*b, *readImage(dir.file("g.exr")));
}

TEST(NativeVsOiio, ExrWrittenByOpenImageIOReadsTheSameNatively) {
    test::TempDir dir;
    const auto b = gbuffer();
    for (const char* compression : {"zip", "piz", "none", "rle", "zips"}) {
        ImageWriteOptions o;
        o.compression = compression;
        oiio().writeImage(*b, dir.file("g.exr"), o);
        expectSame(*b, *readImage(dir.file("g.exr")));
        expectSame(*oiio().readImage(dir.file("g.exr")), *readImage(dir.file("g.exr")));
    }
    ImageWriteOptions half;
    half.halfFloat = true;
    oiio().writeImage(*b, dir.file("h.exr"), half);
    writeImage(*b, dir.file("n.exr"), half);
    expectSame(*oiio().readImage(dir.file("h.exr")), *readImage(dir.file("n.exr")));
}

TEST(NativeVsOiio, HeadersAgree) {
    test::TempDir dir;
    writeImage(*gbuffer(), dir.file("g.exr"));
    const auto fromOiio = oiio().readHeader(dir.file("g.exr"));
    const auto image = readImage(dir.file("g.exr"));
    EXPECT_EQ(fromOiio.width, image->width());
    EXPECT_EQ(fromOiio.height, image->height());
    EXPECT_EQ(fromOiio.channels, image->channels());
}

// A file from another tool: no darkroom:channels, a data window away from
// the origin, half and float channels, colour channels out of order. Both
// readers put channels without a layer first, R, G, B, A first within a
// layer, and keep the rest in the file's order.
TEST(NativeVsOiio, ForeignExrWithOffsetDataWindowReadsTheSame) {
    test::TempDir dir;
    const std::string path = dir.file("foreign.exr");
    const int w = 5, h = 3;
    Imath::Box2i display(Imath::V2i(0, 0), Imath::V2i(19, 19));
    Imath::Box2i data(Imath::V2i(7, 11), Imath::V2i(7 + w - 1, 11 + h - 1));
    Imf::Header header(display, data);
    const char* names[] = {"A", "B", "G", "R", "Z", "diffuse.B", "diffuse.R", "id"};
    std::vector<std::vector<float>> floats(8, std::vector<float>(w * h));
    std::vector<std::vector<Imath::half>> halves(8, std::vector<Imath::half>(w * h));
    std::vector<std::uint32_t> ids(w * h);
    Imf::FrameBuffer fb;
    for (int c = 0; c < 8; ++c) {
        const std::string n = names[c];
        for (int i = 0; i < w * h; ++i) {
            floats[c][i] = float(c) + float(i) / 16.0f;
            halves[c][i] = Imath::half(floats[c][i]);
            ids[i] = std::uint32_t(1000 + i);
        }
        const std::ptrdiff_t origin = 7 + 11 * w;
        if (n == "id") {
            header.channels().insert(n, Imf::Channel(Imf::UINT));
            fb.insert(n, Imf::Slice(Imf::UINT, reinterpret_cast<char*>(ids.data() - origin), 4, 4 * w));
        } else if (c % 2 == 0) {
            header.channels().insert(n, Imf::Channel(Imf::HALF));
            fb.insert(n, Imf::Slice(Imf::HALF, reinterpret_cast<char*>(halves[c].data() - origin), 2, 2 * w));
        } else {
            header.channels().insert(n, Imf::Channel(Imf::FLOAT));
            fb.insert(n, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(floats[c].data() - origin), 4, 4 * w));
        }
    }
    {
        Imf::OutputFile out(path.c_str(), header);
        out.setFrameBuffer(fb);
        out.writePixels(h);
    }
    const auto native = readImage(path);
    expectSame(*oiio().readImage(path), *native);
    ASSERT_EQ(native->width(), w);
    ASSERT_EQ(native->height(), h);
    std::vector<std::string> order;
    for (const auto& c : native->channels()) order.push_back(c.name);
    EXPECT_EQ(order, (std::vector<std::string>{"R", "G", "B", "A", "Z", "id", "diffuse.R", "diffuse.B"}));
    EXPECT_EQ(native->hostFloat("B")[4], float(Imath::half(1.0f + 4.0f / 16.0f)));  // half widened
    EXPECT_EQ(native->hostFloat("G")[2], 2.0f + 2.0f / 16.0f);                        // float exact
    EXPECT_EQ(native->hostUInt("id")[w * h - 1], std::uint32_t(1000 + w * h - 1));
}

TEST(NativeVsOiio, PngPixelsAreIdenticalWhicheverEncoderWroteThem) {
    test::TempDir dir;
    const std::vector<std::vector<std::string>> layouts = {{"R", "G", "B", "A"}, {"R", "G", "B"}, {"Y"}, {"Y", "A"}};
    for (const auto& channels : layouts) {
        const auto b = test::makeImage(37, 23, channels, [](int x, int y, int c) {
            if (x == 3 && y == 4) return std::numeric_limits<float>::quiet_NaN();
            return std::fmod(0.013f * float(x * (c + 1)) + 0.041f * float(y), 1.3f) - 0.1f;
        });
        writeImage(*b, dir.file("native.png"));
        oiio().writeImage(*b, dir.file("oiio.png"), {});
        const auto a = oiio().readImage(dir.file("native.png"));
        const auto o = oiio().readImage(dir.file("oiio.png"));
        expectSame(*o, *a);
        EXPECT_EQ(a->channels().size(), channels.size());
    }
}

TEST(NativeVsOiio, ExrAndPngAloneNeverLoadOpenImageIO) {
    test::TempDir dir;
    if (oiioLoaded()) GTEST_SKIP() << "OpenImageIO was already loaded by an earlier test in this process";
    const auto b = gbuffer();
    writeImage(*b, dir.file("g.exr"));
    readImage(dir.file("g.exr"));
    const auto rgb = test::makeImage(4, 4, {"R", "G", "B"}, [](int x, int, int) { return float(x) / 4.0f; });
    writeImage(*rgb, dir.file("c.png"));
    EXPECT_FALSE(oiioLoaded());
    // Any other format brings the module, and OpenImageIO with it.
    writeImage(*rgb, dir.file("c.tif"));
    EXPECT_TRUE(oiioLoaded());
    expectSame(*readImage(dir.file("c.tif")), *oiio().readImage(dir.file("c.tif")));
}

TEST(NativeVsOiio, SpecialFilesAreRefusedBeforeOpening) {
    try {
        readImage("/dev/zero");
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("/dev/zero"));
        EXPECT_THAT(e.what(), HasSubstr("expected a regular file"));
    }
}
