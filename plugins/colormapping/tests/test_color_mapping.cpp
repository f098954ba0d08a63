// ColorMapping through the plugin registry.
#include "../../normals/tests/simd_targets.h"
#include "test_support.h"

#include <darkroom/colormap.h>
#include <darkroom/error.h>
#include <darkroom/core/run_filter.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace darkroom;
using ::testing::HasSubstr;

namespace {

using Inputs = std::map<std::string, std::vector<Value>>;
const float kNaN = std::numeric_limits<float>::quiet_NaN();
const float kInf = std::numeric_limits<float>::infinity();

FilterRunResult mapImage(const BufferPtr& image, Inputs extra = {}, int threads = 0) {
    auto f = test::pluginRegistry().createFilter("ColorMapping");
    extra["image"] = {Value(image)};
    FilterRunOptions o;
    o.threads = threads;
    return runFilter(*f, extra, o);
}

Color pixel(const Buffer& b, std::size_t i) {
    return {b.hostFloat("R")[i], b.hostFloat("G")[i], b.hostFloat("B")[i], b.hostFloat("A")[i]};
}

void expectColor(const Color& got, const Color& want, float tol, const std::string& what) {
    EXPECT_NEAR(got.r, want.r, tol) << what;
    EXPECT_NEAR(got.g, want.g, tol) << what;
    EXPECT_NEAR(got.b, want.b, tol) << what;
    EXPECT_NEAR(got.a, want.a, tol) << what;
}

// A ramp from -2 to 6 along x with one NaN pixel, all on geometry (finite Z).
std::shared_ptr<WritableBuffer> ramp() {
    return test::makeImage(9, 3, {"Z", "Pressure"}, [](int x, int y, int c) {
        if (c == 0) return 1.0f;
        return x == 4 && y == 1 ? kNaN : -2.0f + float(x);
    });
}

}  // namespace

TEST(ColorMapping, AutomaticRangeMapsMinimumAndMaximumToTheEnds) {
    const auto r = mapImage(ramp());
    const BufferPtr out = r.outputs.at("image").asImage();
    ASSERT_TRUE(out);
    EXPECT_EQ(out->channelNames(), (std::vector<std::string>{"R", "G", "B", "A", "Z"}));
    const auto viridis = loadColorMap("viridis");
    EXPECT_EQ(pixel(*out, 0), viridis.sample(0.0));  // exactly
    EXPECT_EQ(pixel(*out, 8), viridis.sample(1.0));
    expectColor(pixel(*out, 2), viridis.sample(0.25), 1e-4f, "quarter");
    expectColor(pixel(*out, 9 + 4), Color{1, 1, 0, 1}, 0.0f, "NaN takes nanColor");
    EXPECT_EQ(r.outputs.at("usedMinimum").asFloat(), -2.0);
    EXPECT_EQ(r.outputs.at("usedMaximum").asFloat(), 6.0);
}

TEST(ColorMapping, ManualRangeClampsAndCanBeReversed) {
    const auto m = loadColorMap("magma");
    const auto r = mapImage(ramp(), {{"range", {Value("manual")}}, {"minimum", {Value(0.0)}},
                                     {"maximum", {Value(4.0)}}, {"colormap", {Value("magma")}}});
    const BufferPtr out = r.outputs.at("image").asImage();
    EXPECT_EQ(pixel(*out, 0), m.sample(0.0));  // -2 is below the range
    EXPECT_EQ(pixel(*out, 2), m.sample(0.0));  // 0
    expectColor(pixel(*out, 3), m.sample(0.25), 1e-4f, "1 of [0, 4]");
    EXPECT_EQ(pixel(*out, 6), m.sample(1.0));  // 4
    EXPECT_EQ(pixel(*out, 8), m.sample(1.0));  // 6 is above

    const auto flipped = mapImage(ramp(), {{"range", {Value("manual")}}, {"minimum", {Value(4.0)}},
                                           {"maximum", {Value(0.0)}}, {"colormap", {Value("magma")}}});
    EXPECT_EQ(pixel(*flipped.outputs.at("image").asImage(), 2), m.sample(1.0));
}

TEST(ColorMapping, OnePixelAndConstantImagesUseTheMiddleOfTheMap) {
    const auto one = test::makeImage(1, 1, {"s"}, [](int, int, int) { return 42.0f; });
    const auto r = mapImage(one, {{"colormap", {Value("plasma")}}});
    expectColor(pixel(*r.outputs.at("image").asImage(), 0), loadColorMap("plasma").sample(0.5), 1e-4f, "1x1");
    EXPECT_EQ(r.outputs.at("usedMinimum").asFloat(), 42.0);
}

TEST(ColorMapping, AllNanImageIsAllNanColour) {
    const auto nan = test::makeImage(3, 2, {"Z", "s"}, [](int, int, int c) { return c == 0 ? 1.0f : kNaN; });
    const Color grey{0.2f, 0.2f, 0.2f, 0.5f};
    const auto r = mapImage(nan, {{"nanColor", {Value(grey)}}});
    const BufferPtr out = r.outputs.at("image").asImage();
    for (std::size_t i = 0; i < out->pixelCount(); ++i) EXPECT_EQ(pixel(*out, i), grey);
    EXPECT_TRUE(std::isnan(r.outputs.at("usedMinimum").asFloat()));
}

TEST(ColorMapping, WithoutDepthNanIsTheTransparentBackground) {
    // ParaView's float images mark the background with NaN and store no depth.
    const auto img = test::makeImage(3, 1, {"s"}, [](int x, int, int) { return x == 1 ? kNaN : float(x); });
    const auto r = mapImage(img, {{"nanColor", {Value(Color{1, 1, 0, 1})}}});
    const BufferPtr out = r.outputs.at("image").asImage();
    EXPECT_EQ(pixel(*out, 1), (Color{0, 0, 0, 0}));
    EXPECT_EQ(pixel(*out, 0), loadColorMap("viridis").sample(0.0));
    EXPECT_EQ(pixel(*out, 2), loadColorMap("viridis").sample(1.0));
}

TEST(ColorMapping, UsesTheColourMapTheDatabaseStoresUnlessOneIsAsked) {
    const std::string dir = test::sharedData("cinema/ttk_extracts_001.cdb/colormap");
    if (dir.empty()) GTEST_SKIP() << "../shared/data/cinema is absent";
    auto img = ramp();
    img->metadata().attributes["colormap.Pressure"] = dir + "/blackbody.json";
    const auto stored = mapImage(img);
    const auto bb = loadColorMap(dir + "/blackbody.json");
    EXPECT_EQ(pixel(*stored.outputs.at("image").asImage(), 8), bb.sample(1.0));
    EXPECT_EQ(stored.outputs.at("usedColormap").asString(), dir + "/blackbody.json");
    // A map asked for wins; another channel's stored map is not used.
    const auto asked = mapImage(img, {{"colormap", {Value("magma")}}});
    EXPECT_EQ(pixel(*asked.outputs.at("image").asImage(), 8), loadColorMap("magma").sample(1.0));
    img->metadata().attributes.erase("colormap.Pressure");
    img->metadata().attributes["colormap.Other"] = dir + "/blackbody.json";
    const auto other = mapImage(img);
    EXPECT_EQ(other.outputs.at("usedColormap").asString(), "viridis");
}

TEST(ColorMapping, DepthPassesThroughAndBackgroundIsTransparentAndIgnored) {
    // Background pixels hold a huge scalar that must not stretch the range.
    const auto img = test::makeImage(4, 1, {"Z", "T"}, [](int x, int, int c) {
        if (c == 0) return x == 3 ? kInf : 1.0f + float(x);
        return x == 3 ? 1e9f : float(x);
    });
    const auto r = mapImage(img, {{"opacity", {Value(0.5)}}});
    const BufferPtr out = r.outputs.at("image").asImage();
    EXPECT_EQ(out->channelNames(), (std::vector<std::string>{"R", "G", "B", "A", "Z"}));
    EXPECT_EQ(r.outputs.at("usedMaximum").asFloat(), 2.0);
    EXPECT_EQ(pixel(*out, 3), (Color{0, 0, 0, 0}));
    EXPECT_EQ(pixel(*out, 2).a, 0.5f);
    for (int x = 0; x < 4; ++x) EXPECT_EQ(out->hostFloat("Z")[x], img->hostFloat("Z")[x]);
}

TEST(ColorMapping, ChoosesChannelsAndMapsUInt32) {
    auto img = makeCpuBuffer(3, 1, {{"Z", ChannelType::Float32}, {"id", ChannelType::UInt32},
                                    {"a", ChannelType::Float32}, {"b", ChannelType::Float32}});
    for (int x = 0; x < 3; ++x) {
        img->writeFloat("Z")[x] = 1;
        img->writeUInt("id")[x] = std::uint32_t(x * 10);
        img->writeFloat("a")[x] = float(x);
        img->writeFloat("b")[x] = float(2 - x);
    }
    const auto m = loadColorMap("viridis");
    // Default: the first float channel that is not Z or A -> "a".
    EXPECT_EQ(pixel(*mapImage(img).outputs.at("image").asImage(), 0), m.sample(0.0));
    EXPECT_EQ(pixel(*mapImage(img, {{"channel", {Value("b")}}}).outputs.at("image").asImage(), 0), m.sample(1.0));
    const auto ids = mapImage(img, {{"channel", {Value("id")}}});
    EXPECT_EQ(pixel(*ids.outputs.at("image").asImage(), 2), m.sample(1.0));
    EXPECT_EQ(ids.outputs.at("usedMaximum").asFloat(), 20.0);
    try {
        mapImage(img, {{"channel", {Value("Elevation")}}});
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("'Elevation'"));
        EXPECT_THAT(e.what(), HasSubstr("id"));
    }
}

TEST(ColorMapping, ParaViewFileAndItsNanColour) {
    const std::string dir = test::sharedData("cinema/ttk_extracts_001.cdb/colormap");
    if (dir.empty()) GTEST_SKIP() << "../shared/data/cinema is absent";
    const auto img = ramp();
    auto f = test::pluginRegistry().createFilter("ColorMapping");
    FilterRunOptions o;
    o.inputBase = dir;  // a relative colour-map path is resolved like a pipeline's
    const auto r = runFilter(*f, {{"image", {Value(BufferPtr(img))}}, {"colormap", {Value("blackbody.json")}},
                                  {"useMapNanColor", {Value(true)}}}, o);
    const BufferPtr out = r.outputs.at("image").asImage();
    const auto bb = loadColorMap(dir + "/blackbody.json");
    EXPECT_EQ(pixel(*out, 8), bb.sample(1.0));
    EXPECT_EQ(pixel(*out, 9 + 4), bb.nanColor);
}

TEST(ColorMapping, MissingColourMapFileIsAnError) {
    try {
        mapImage(ramp(), {{"colormap", {Value("/nonexistent/map.json")}}});
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("/nonexistent/map.json"));
    }
}

TEST(ColorMapping, ResultDoesNotDependOnThreadCount) {
    const auto big = test::makeImage(301, 257, {"Z", "s"}, [](int x, int y, int c) {
        if (c == 0) return (x * 7 + y) % 13 == 0 ? kInf : 1.0f;
        return (x * 31 + y * 17) % 101 == 0 ? kNaN : std::sin(float(x) * 0.05f) * std::cos(float(y) * 0.03f);
    });
    const auto one = mapImage(big, {{"colormap", {Value("cool-to-warm")}}}, 1);
    const auto many = mapImage(big, {{"colormap", {Value("cool-to-warm")}}}, 8);
    EXPECT_TRUE(identical(*one.outputs.at("image").asImage(), *many.outputs.at("image").asImage()));
}

TEST(ColorMapping, LogScaleMapsDecadesEvenlyAndIgnoresNonPositiveValuesForItsRange) {
    // 0.01, 0.1, 1, 10, 100 along x, then 0 and -5 (below any log range).
    const float values[7] = {0.01f, 0.1f, 1.0f, 10.0f, 100.0f, 0.0f, -5.0f};
    const auto img = test::makeImage(7, 1, {"Pressure"}, [&](int x, int, int) { return values[x]; });
    const auto v = loadColorMap("viridis");
    const auto r = mapImage(img, {{"scale", {Value("log")}}});
    const BufferPtr out = r.outputs.at("image").asImage();
    EXPECT_FLOAT_EQ(float(r.outputs.at("usedMinimum").asFloat()), 0.01f);
    EXPECT_FLOAT_EQ(float(r.outputs.at("usedMaximum").asFloat()), 100.0f);
    EXPECT_EQ(r.outputs.at("usedScale").asString(), "log");
    EXPECT_EQ(r.outputs.at("usedColormap").asString(), "viridis");
    for (int k = 0; k < 5; ++k)
        expectColor(pixel(*out, std::size_t(k)), v.sample(0.25 * k), 2e-4f, "decade " + std::to_string(k));
    EXPECT_EQ(pixel(*out, 5), v.sample(0.0));
    EXPECT_EQ(pixel(*out, 6), v.sample(0.0));

    const auto linear = mapImage(img);
    EXPECT_EQ(linear.outputs.at("usedScale").asString(), "linear");
    EXPECT_EQ(linear.outputs.at("usedMinimum").asFloat(), -5.0);
}

TEST(ColorMapping, LogScaleNeedsAPositiveManualRange) {
    try {
        mapImage(ramp(), {{"scale", {Value("log")}}, {"range", {Value("manual")}}, {"minimum", {Value(0.0)}},
                          {"maximum", {Value(10.0)}}});
        FAIL() << "expected an error";
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("log scale needs a positive manual range"));
    }
}

// The mapping and the range run vectors of pixels with the best SIMD
// instructions of the CPU: every instruction set gives the same bits and the
// same range (automatic, manual, reversed, empty), with NaN, ±inf and
// background among the values.
TEST(ColorMapping, ResultDoesNotDependOnTheSimdInstructionSet) {
    const auto img = test::makeImage(67, 45, {"Z", "s"}, [](int x, int y, int c) {
        if (c == 0) return (x * 7 + y) % 13 == 0 ? kInf : 1.0f;
        if ((x * 31 + y * 17) % 101 == 0) return kNaN;
        if ((x * 5 + y) % 97 == 0) return (x % 2 ? 1.0f : -1.0f) * kInf;
        return std::sin(float(x) * 0.05f) * std::cos(float(y) * 0.03f);
    });
    for (const Inputs& p : {Inputs{},
                            Inputs{{"range", {Value("manual")}}, {"minimum", {Value(-0.3)}}, {"maximum", {Value(0.6)}}},
                            Inputs{{"range", {Value("manual")}}, {"minimum", {Value(0.6)}}, {"maximum", {Value(-0.3)}}},
                            Inputs{{"range", {Value("manual")}}, {"minimum", {Value(0.1)}}, {"maximum", {Value(0.1)}}}}) {
        const auto results = test::resultsPerSimdTarget([&] { return mapImage(img, p); });
        for (const auto& [target, r] : results) {
            EXPECT_TRUE(identical(*r.outputs.at("image").asImage(), *results.front().second.outputs.at("image").asImage()))
                << target << " differs from " << results.front().first;
            for (const char* v : {"usedMinimum", "usedMaximum"}) {
                const double got = r.outputs.at(v).asFloat(), want = results.front().second.outputs.at(v).asFloat();
                EXPECT_TRUE(got == want || (std::isnan(got) && std::isnan(want))) << v << " " << target;
            }
        }
    }
}

// Vectors of pixels that are all background (Z = +inf) are written as
// zeros without their lookups; a lone lit pixel among background, at every
// place of a vector and in the row's overlapping last vector, keeps its
// colour, the same as in a picture with no background at all.
TEST(ColorMapping, LongBackgroundRunsAreZeroAndLitPixelsAmongThemKeepTheirColour) {
    const int w = 67;
    const auto value = [](int x) { return 0.25f + 0.01f * float(x); };
    const auto lit = [](int x, int y) { return x == y % w || x >= 60; };
    const auto img = test::makeImage(w, 40, {"Z", "s"}, [&](int x, int y, int c) {
        if (c == 0) return lit(x, y) ? 1.0f : kInf;
        return value(x);
    });
    const auto plain = test::makeImage(w, 40, {"Z", "s"}, [&](int x, int, int c) { return c == 0 ? 1.0f : value(x); });
    const Inputs range{{"range", {Value("manual")}}, {"minimum", {Value(0.0)}}, {"maximum", {Value(1.0)}}};
    const auto out = mapImage(img, range).outputs.at("image").asImage();
    const auto reference = mapImage(plain, range).outputs.at("image").asImage();
    for (int y = 0; y < 40; ++y)
        for (int x = 0; x < w; ++x) {
            const Color got = pixel(*out, std::size_t(y * w + x));
            const Color want = lit(x, y) ? pixel(*reference, std::size_t(y * w + x)) : Color{0, 0, 0, 0};
            expectColor(got, want, 0.0f, "pixel " + std::to_string(x) + ", " + std::to_string(y));
        }
}
