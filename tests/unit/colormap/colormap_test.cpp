// Colour-map presets against published values, and ParaView JSON import.
#include "test_support.h"

#include <darkroom/colormap.h>
#include <darkroom/error.h>
#include <darkroom/srgb.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

using namespace darkroom;
using ::testing::HasSubstr;

namespace {

// Expects the sRGB encoding of a linear colour to be the 8-bit #rrggbb given,
// within `tol` code values.
void expectHex(const Color& c, unsigned hex, double tol, const std::string& what) {
    const double want[3] = {double((hex >> 16) & 255), double((hex >> 8) & 255), double(hex & 255)};
    const double got[3] = {linearToSrgb(c.r) * 255.0, linearToSrgb(c.g) * 255.0, linearToSrgb(c.b) * 255.0};
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i], want[i], tol) << what << " channel " << i;
}

void expectSrgb(const Color& c, double r, double g, double b, double tol, const std::string& what) {
    EXPECT_NEAR(linearToSrgb(c.r), r, tol) << what;
    EXPECT_NEAR(linearToSrgb(c.g), g, tol) << what;
    EXPECT_NEAR(linearToSrgb(c.b), b, tol) << what;
}

std::string writeJson(const test::TempDir& dir, const std::string& name, const std::string& text) {
    const std::string path = dir.file(name);
    test::writeText(path, text);
    return path;
}

}  // namespace

TEST(ColorMap, ListsTheRequiredPresets) {
    const auto names = colorMapPresets();
    for (const char* n : {"viridis", "plasma", "inferno", "magma", "cool-to-warm", "blackbody", "grayscale"})
        EXPECT_NE(std::find(names.begin(), names.end(), n), names.end()) << n;
    for (const auto& n : names) {
        const auto m = loadColorMap(n);
        EXPECT_GE(m.points.size(), 2u) << n;
        EXPECT_EQ(m.points.front().x, 0.0) << n;
        EXPECT_EQ(m.points.back().x, 1.0) << n;
    }
}

// Endpoints and midpoints as published for the matplotlib maps (viridisLite's
// 3-colour palettes), within 2 code values.
TEST(ColorMap, MatplotlibMapsMatchPublishedColours) {
    struct Case {
        const char* name;
        unsigned start, middle, end;
    };
    for (const Case& c : {Case{"viridis", 0x440154, 0x21908C, 0xFDE725}, Case{"plasma", 0x0D0887, 0xCC4678, 0xF0F921},
                          Case{"inferno", 0x000004, 0xBB3754, 0xFCFFA4}, Case{"magma", 0x000004, 0xB63679, 0xFCFDBF}}) {
        const auto m = loadColorMap(c.name);
        expectHex(m.sample(0.0), c.start, 1.0, std::string(c.name) + "(0)");
        expectHex(m.sample(0.5), c.middle, 2.0, std::string(c.name) + "(0.5)");
        expectHex(m.sample(1.0), c.end, 1.0, std::string(c.name) + "(1)");
    }
}

// Moreland's published 33-entry cool-warm table (8-bit), which the Msh
// interpolation must reproduce from the end points alone.
TEST(ColorMap, CoolToWarmFollowsMorelandsTable) {
    const auto m = loadColorMap("cool-to-warm");
    EXPECT_EQ(m.space, ColorMapSpace::Diverging);
    expectHex(m.sample(0.0), 0x3B4CC0, 0.6, "0");
    expectHex(m.sample(0.125), 0x6282EA, 1.0, "0.125");   // 98 130 234
    expectHex(m.sample(0.25), 0x8DB0FE, 1.0, "0.25");     // 141 176 254
    expectHex(m.sample(0.375), 0xB8D0F9, 1.0, "0.375");   // 184 208 249
    expectHex(m.sample(0.625), 0xF5C4AD, 1.0, "0.625");   // 245 196 173
    expectHex(m.sample(0.75), 0xF49A7B, 1.0, "0.75");     // 244 154 123
    expectHex(m.sample(0.875), 0xDE604D, 1.0, "0.875");   // 222 96 77
    expectHex(m.sample(1.0), 0xB40426, 0.6, "1");
}

TEST(ColorMap, BlackbodyGrayscaleAndRainbow) {
    const auto bb = loadColorMap("blackbody");
    expectSrgb(bb.sample(0.0), 0, 0, 0, 1e-6, "blackbody(0)");
    expectSrgb(bb.sample(0.4), 0.901960784314, 0, 0, 1e-5, "blackbody(0.4)");
    expectSrgb(bb.sample(1.0), 1, 1, 1, 1e-6, "blackbody(1)");
    EXPECT_TRUE(bb.hasNanColor);
    // ParaView interpolates "RGB" maps in the stored (sRGB) values: the middle
    // of black-to-white is sRGB 0.5, not linear 0.5.
    expectSrgb(loadColorMap("grayscale").sample(0.5), 0.5, 0.5, 0.5, 1e-5, "grayscale(0.5)");
    // HSV: blue, cyan, green, yellow, red.
    const auto rb = loadColorMap("rainbow");
    expectSrgb(rb.sample(0.25), 0, 1, 1, 1e-5, "rainbow(0.25)");
    expectSrgb(rb.sample(0.5), 0, 1, 0, 1e-5, "rainbow(0.5)");
}

TEST(ColorMap, SamplingClampsAndGivesNanItsColour) {
    const auto m = loadColorMap("viridis");
    EXPECT_EQ(m.sample(-5.0), m.sample(0.0));
    EXPECT_EQ(m.sample(7.0), m.sample(1.0));
    EXPECT_EQ(m.sample(std::nan("")), m.nanColor);
    const auto t = m.table(5);
    EXPECT_EQ(t.front(), m.sample(0.0));
    EXPECT_EQ(t[2], m.sample(0.5));
    EXPECT_EQ(t.back(), m.sample(1.0));
}

TEST(ColorMap, NamesAreMatchedLooselyAndParaViewNamesWork) {
    EXPECT_TRUE(isColorMapPreset("VIRIDIS"));
    EXPECT_TRUE(isColorMapPreset("Viridis (matplotlib)"));
    EXPECT_TRUE(isColorMapPreset("Cool to Warm"));
    EXPECT_TRUE(isColorMapPreset("Black-Body Radiation"));
    EXPECT_TRUE(isColorMapPreset("grey"));
    EXPECT_FALSE(isColorMapPreset("no-such-map"));
    EXPECT_EQ(loadColorMap("Cool to Warm").name, "cool-to-warm");
}

TEST(ColorMap, ParaViewJsonFromATtkDatabase) {
    const std::string dir = test::sharedData("cinema/ttk_extracts_001.cdb/colormap");
    if (dir.empty()) GTEST_SKIP() << "../shared/data/cinema is absent";
    const auto bb = loadColorMap(dir + "/blackbody.json");
    EXPECT_EQ(bb.name, "Black-Body Radiation");
    EXPECT_EQ(bb.points.size(), 4u);
    EXPECT_EQ(bb.space, ColorMapSpace::RGB);
    ASSERT_TRUE(bb.hasNanColor);
    expectSrgb(bb.nanColor, 0.0, 0.498039215686, 1.0, 1e-6, "NanColor");
    EXPECT_EQ(bb.nanColor.a, 1.0f);

    const auto cw = loadColorMap(dir + "/cooltowarm.json");
    EXPECT_EQ(cw.points.size(), 3u);
    EXPECT_EQ(cw.space, ColorMapSpace::Diverging);
    expectSrgb(cw.nanColor, 1, 1, 0, 1e-6, "NanColor");
    // The file and the preset describe the same map.
    const auto preset = loadColorMap("cool-to-warm");
    for (double t : {0.0, 0.1, 0.3, 0.5, 0.7, 0.95, 1.0}) {
        const Color a = cw.sample(t), b = preset.sample(t);
        EXPECT_NEAR(a.r, b.r, 1e-5) << t;
        EXPECT_NEAR(a.g, b.g, 1e-5) << t;
        EXPECT_NEAR(a.b, b.b, 1e-5) << t;
    }
}

TEST(ColorMap, JsonObjectWithDataRangeIsNormalised) {
    test::TempDir dir;
    const auto path = writeJson(dir, "lab.json", R"({"Name": "Mine", "ColorSpace": "Lab",
        "RGBPoints": [-10, 0, 0, 0,  0, 1, 0, 0,  30, 1, 1, 1], "NanColor": [0.5, 0.5, 0.5, 0.25]})");
    const auto m = loadColorMap(path);
    EXPECT_EQ(m.name, "Mine");
    EXPECT_EQ(m.space, ColorMapSpace::Lab);
    ASSERT_EQ(m.points.size(), 3u);
    EXPECT_DOUBLE_EQ(m.points[1].x, 0.25);
    expectSrgb(m.sample(0.25), 1, 0, 0, 1e-5, "control point");
    EXPECT_FLOAT_EQ(m.nanColor.a, 0.25f);
    // Lab interpolation from black to red stays on the red hue, brighter than linear RGB.
    const Color mid = m.sample(0.125);
    EXPECT_NEAR(mid.g, 0.0, 0.02);
    EXPECT_GT(mid.r, 0.1);
}

TEST(ColorMap, ArrayPicksTheFirstEntryWithRgbPoints) {
    test::TempDir dir;
    const auto path = writeJson(dir, "many.json", R"([{"Name": "categorical", "IndexedColors": [1, 0, 0]},
        {"Name": "second", "RGBPoints": [0, 0, 0, 1, 1, 1, 0, 0]}, {"Name": "third", "RGBPoints": [0, 1, 1, 1, 1, 0, 0, 0]}])");
    EXPECT_EQ(loadColorMap(path).name, "second");
}

TEST(ColorMap, BadFilesAreReportedWithTheFileName) {
    test::TempDir dir;
    auto expectError = [&](const std::string& path, const std::string& why) {
        try {
            loadColorMap(path);
            FAIL() << "no error for " << path;
        } catch (const Error& e) {
            EXPECT_THAT(e.what(), HasSubstr(path));
            EXPECT_THAT(e.what(), HasSubstr(why));
        }
    };
    expectError(dir.file("absent.json"), "viridis");  // names the presets too
    expectError(writeJson(dir, "broken.json", "[{\"RGBPoints\": [0, 0, 0\n"), "line 2");
    expectError(writeJson(dir, "odd.json", R"({"RGBPoints": [0, 0, 0, 0, 1, 1]})"), "quadruples");
    expectError(writeJson(dir, "unsorted.json", R"({"RGBPoints": [1, 0, 0, 0, 0, 1, 1, 1]})"), "sorted");
    expectError(writeJson(dir, "text.json", R"({"RGBPoints": [0, "red", 0, 0, 1, 1, 1, 1]})"), "RGBPoints[0].r");
    expectError(writeJson(dir, "space.json", R"({"RGBPoints": [0, 0, 0, 0, 1, 1, 1, 1], "ColorSpace": "Step"})"),
                "Step");
    expectError(writeJson(dir, "none.json", R"([{"Name": "x"}])"), "RGBPoints");
    expectError(writeJson(dir, "scalar.json", "42"), "array");
    try {
        loadColorMap("");
        FAIL() << "no error for an empty name";
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("viridis"));
    }
}
