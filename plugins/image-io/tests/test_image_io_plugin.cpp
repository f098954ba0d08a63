// ImageReader and ImageWriter through the plugin registry, as a pipeline runs them.
#include "test_support.h"

#include <darkroom/error.h>
#include <darkroom/data/image_io.h>
#include <darkroom/core/run_filter.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

using namespace darkroom;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

namespace {

using Inputs = std::map<std::string, std::vector<Value>>;

FilterRunResult run(const std::string& type, const Inputs& in, const FilterRunOptions& o = {}) {
    auto f = test::pluginRegistry().createFilter(type);
    return runFilter(*f, in, o);
}

std::shared_ptr<WritableBuffer> sample() {
    auto b = test::makeImage(9, 4, {"Z", "Temperature"}, [](int x, int y, int c) {
        return c == 0 ? (x == 0 ? INFINITY : 2.0f + float(y)) : std::sin(float(x * 4 + y)) * 300.0f;
    });
    Camera cam;
    cam.position = {1, 2, 3};
    cam.width = 9;
    cam.height = 4;
    b->metadata().camera = cam;
    b->metadata().attributes["units.Temperature"] = "K";
    return b;
}

}  // namespace

TEST(ImageIoPlugin, RegistersReaderAndWriter) {
    auto& r = test::pluginRegistry();
    ASSERT_NE(r.filter("ImageReader"), nullptr);
    ASSERT_NE(r.filter("ImageWriter"), nullptr);
    EXPECT_EQ(r.ports("ImageWriter").outputs.size(), 0u) << "a sink";
    EXPECT_EQ(r.ports("ImageReader").input("path")->type, PortType::Path);
    EXPECT_EQ(r.ports("ImageWriter").input("path")->type, PortType::OutputPath) << "found by kind by the batch";
    EXPECT_EQ(r.ports("ImageWriter").input("compression")->type, PortType::Enum);
}

TEST(ImageIoPlugin, WriterCreatesTheFolderAndReaderReadsBackExactly) {
    test::TempDir dir;
    const auto b = sample();
    FilterRunOptions o;
    o.outputDir = dir.path();
    // A relative path lands below the output directory; missing folders are made.
    run("ImageWriter", {{"image", {Value(BufferPtr(b))}}, {"path", {Value("deep/er/out.exr")}}}, o);
    ASSERT_TRUE(fs::exists(dir.file("deep/er/out.exr")));

    FilterRunOptions ro;
    ro.inputBase = dir.path();
    const auto r = run("ImageReader", {{"path", {Value("deep/er/out.exr")}}}, ro);
    const BufferPtr img = r.outputs.at("image").asImage();
    ASSERT_TRUE(img);
    EXPECT_EQ(img->metadata().attributes.at("source"), "deep/er/out.exr");
    // Apart from the provenance the reader adds, the buffer is the one written.
    auto copy = makeCpuBuffer(img->width(), img->height(), img->channels());
    for (const auto& c : img->channels())
        std::copy_n(img->hostFloat(c.name), img->pixelCount(), copy->writeFloat(c.name));
    copy->metadata() = img->metadata();
    copy->metadata().attributes.erase("source");
    EXPECT_TRUE(identical(*b, *copy));
}

TEST(ImageIoPlugin, WriterOptionsReachTheFile) {
    test::TempDir dir;
    const auto b = sample();
    run("ImageWriter", {{"image", {Value(BufferPtr(b))}},
                        {"path", {Value(dir.file("half.exr"))}},
                        {"compression", {Value("piz")}},
                        {"half", {Value(true)}}});
    const auto h = readImage(dir.file("half.exr"));
    EXPECT_EQ(h->hostFloat("Z")[10], b->hostFloat("Z")[10]);  // depth stays float32
    EXPECT_NE(h->hostFloat("Temperature")[5], b->hostFloat("Temperature")[5]);  // half rounds
    EXPECT_NEAR(h->hostFloat("Temperature")[5], b->hostFloat("Temperature")[5], 0.25f);

    run("ImageWriter", {{"image", {Value(BufferPtr(b))}},
                        {"path", {Value(dir.file("t.png"))}},
                        {"channels", {Value("Temperature")}}});
    EXPECT_EQ(readImage(dir.file("t.png"))->channelNames(), std::vector<std::string>{"Y"});
}

TEST(ImageIoPlugin, ErrorsNameTheProblem) {
    test::TempDir dir;
    try {
        run("ImageReader", {});
        FAIL() << "no error for an empty path";
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("path"));
    }
    try {
        run("ImageReader", {{"path", {Value(dir.file("absent.png"))}}});
        FAIL() << "no error for a missing file";
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr(dir.file("absent.png")));
    }
    try {
        run("ImageWriter", {{"image", {Value(BufferPtr(sample()))}}, {"path", {Value(dir.file("x.png"))}},
                            {"channels", {Value("R, G")}}});
        FAIL() << "no error for missing channels";
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("'R'"));
    }
}
