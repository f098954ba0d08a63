// pycinema's .h5 products (docs/formats.md, "pycinema's HDF5 images"): what
// CinemaWriter writes with productExtension ".h5" reads back through
// readCinemaProduct with its values, its orientation (row 0 at the top) and
// its camera; files that are not such images are refused naming the file.
// The exchange with pycinema's own reader and writer (h5py) is tested in
// python/tests/test_pycinema_h5.py.
#include "input_error.h"
#include "test_support.h"

#include <darkroom/srgb.h>
#include <darkroom/data/cinema/product.h>
#include <darkroom/data/cinema/writer.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

using namespace darkroom;
using ::testing::HasSubstr;

namespace {

constexpr int W = 5, H = 3;
const float kInf = std::numeric_limits<float>::infinity();

// An asymmetric image: temperature = 10 y + x (row y from the top), depth
// growing to the right with one background pixel, a red-green ramp, ids.
std::shared_ptr<WritableBuffer> pattern() {
    auto b = makeCpuBuffer(W, H, {"temperature", "Z", "R", "G", "B", "A", {"id", ChannelType::UInt32}});
    float *t = b->writeFloat("temperature"), *z = b->writeFloat("Z");
    float *r = b->writeFloat("R"), *g = b->writeFloat("G"), *bl = b->writeFloat("B"), *a = b->writeFloat("A");
    std::uint32_t* id = b->writeUInt("id");
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const int i = y * W + x;
            t[i] = float(10 * y + x);
            z[i] = 2.f + 0.5f * float(x) + 0.25f * float(y);
            r[i] = float(x) / (W - 1);
            g[i] = float(y) / (H - 1);
            bl[i] = 0.25f;
            a[i] = 1.f;
            id[i] = std::uint32_t(100 + i);
        }
    z[W - 1] = kInf;  // top-right: background
    Camera c;
    c.position = {1, 2, 3};
    c.forward = {0, 0, -1};
    c.up = {0, 1, 0};
    c.fovYDegrees = 40;
    c.width = W;
    c.height = H;
    b->metadata().camera = c;
    b->metadata().attributes["units.temperature"] = "K";
    return b;
}

std::string writeOneEntry(const test::TempDir& dir, const Buffer& image) {
    CinemaWriterOptions o;
    o.productExtension = ".h5";
    CinemaWriter w(dir.file("db.cdb"), {"time", "kind"}, o);
    const CinemaParameters p{{"time", 0.5}, {"kind", "fine"}};
    w.addEntry(p, image);
    const std::string file = dir.file("db.cdb/" + w.entryFileName(p));
    w.finish();
    return file;
}

}  // namespace

TEST(H5Product, RoundTripKeepsValuesRowsTopToBottomAndTheCamera) {
    test::TempDir dir;
    const auto image = pattern();
    const std::string file = writeOneEntry(dir, *image);
    EXPECT_EQ(std::filesystem::path(file).extension(), ".h5");
    Diagnostics warnings;
    const auto back = readCinemaProduct(file, &warnings);
    EXPECT_TRUE(warnings.empty()) << warnings.front().str();
    ASSERT_EQ(back->width(), W);
    ASSERT_EQ(back->height(), H);
    const float* t = back->requireFloat("temperature");
    EXPECT_EQ(t[0], 0.f);                   // top-left
    EXPECT_EQ(t[W - 1], 4.f);               // top-right
    EXPECT_EQ(t[(H - 1) * W], 20.f);        // bottom-left
    EXPECT_EQ(t[H * W - 1], 24.f);          // bottom-right
    const float* z = back->requireFloat("Z");
    const float* zIn = image->hostFloat("Z");
    for (int i = 0; i < W * H; ++i)
        if (std::isinf(zIn[i]))
            EXPECT_EQ(z[i], kInf) << i;
        else
            EXPECT_NEAR(z[i], zIn[i], 1e-5f * zIn[i]) << i;
    // Colour is stored as pycinema's 8-bit sRGB rgba: within half a code value.
    const float* r = back->requireFloat("R");
    const float* g = back->requireFloat("G");
    for (int i = 0; i < W * H; ++i) {
        EXPECT_NEAR(linearToSrgb(r[i]), linearToSrgb(image->hostFloat("R")[i]), 0.5f / 255 + 1e-6f) << i;
        EXPECT_NEAR(linearToSrgb(g[i]), linearToSrgb(image->hostFloat("G")[i]), 0.5f / 255 + 1e-6f) << i;
    }
    EXPECT_EQ(back->requireFloat("A")[7], 1.f);
    const std::uint32_t* id = back->requireUInt("id");
    for (int i = 0; i < W * H; ++i) EXPECT_EQ(id[i], std::uint32_t(100 + i));
    ASSERT_TRUE(back->metadata().camera);
    EXPECT_EQ(*back->metadata().camera, *image->metadata().camera);
    const auto& attrs = back->metadata().attributes;
    EXPECT_EQ(attrs.at("time"), "0.5");  // the entry's row, as pycinema keeps it in meta
    EXPECT_EQ(attrs.at("kind"), "fine");
    EXPECT_EQ(attrs.at("units.temperature"), "K");
    EXPECT_EQ(attrs.at("source"), file);
}

TEST(H5Product, AnOrthographicCameraKeepsItsViewHeight) {
    test::TempDir dir;
    auto image = pattern();
    image->metadata().camera->projection = Camera::Projection::Orthographic;
    image->metadata().camera->viewHeight = 7.5;
    const auto back = readCinemaProduct(writeOneEntry(dir, *image));
    ASSERT_TRUE(back->metadata().camera);
    EXPECT_EQ(back->metadata().camera->projection, Camera::Projection::Orthographic);
    EXPECT_EQ(back->metadata().camera->viewHeight, 7.5);
}

TEST(H5Product, AFileThatIsNotHdf5IsRefusedNamingIt) {
    test::TempDir dir;
    const std::string file = dir.file("x.h5");
    std::ofstream(file) << "channels and meta, but no HDF5";
    const std::string msg = test::inputError([&] { (void)readCinemaProduct(file); });
    EXPECT_THAT(msg, HasSubstr(file));
    EXPECT_THAT(msg, HasSubstr("not an HDF5 file"));
}

TEST(H5Product, ATruncatedFileIsRefusedNotCrashed) {
    test::TempDir dir;
    const std::string file = writeOneEntry(dir, *pattern());
    const auto size = std::filesystem::file_size(file);
    for (const auto keep : {std::uintmax_t(8), size / 4, size / 2, size - 16}) {
        std::filesystem::resize_file(file, keep);
        const std::string msg = test::inputError([&] { (void)readCinemaProduct(file); });
        EXPECT_THAT(msg, HasSubstr(file)) << keep;
    }
}
