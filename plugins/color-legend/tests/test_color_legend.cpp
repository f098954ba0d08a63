// ColorLegend: tick values at round numbers with known answers (linear and
// log), tick marks drawn within half a pixel of value -> position, the bar's
// colours equal to the map's, layout that scales with the image, anchors,
// and clear errors.
#include "legend_layout.h"
#include "nice_ticks.h"
#include "test_support.h"

#include <darkroom/colormap.h>
#include <darkroom/error.h>
#include <darkroom/core/run_filter.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace darkroom;
using namespace darkroom::legend;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

namespace {

std::vector<double> values(const std::vector<Tick>& t) {
    std::vector<double> v;
    for (const auto& x : t) v.push_back(x.value);
    return v;
}
std::vector<std::string> labels(const std::vector<Tick>& t) {
    std::vector<std::string> v;
    for (const auto& x : t) v.push_back(x.label);
    return v;
}

using Inputs = std::map<std::string, std::vector<Value>>;

FilterRunResult drawLegend(const BufferPtr& image, Inputs extra) {
    auto f = test::pluginRegistry().createFilter("ColorLegend");
    extra["image"] = {Value(image)};
    FilterRunOptions o;
    o.threads = 2;
    return runFilter(*f, extra, o);
}

std::shared_ptr<WritableBuffer> blackImage(int w, int h) {
    return test::makeImage(w, h, {"R", "G", "B", "A"}, [](int, int, int c) { return c == 3 ? 1.0f : 0.0f; });
}

LegendStyle styleFor(int w, int h, Orientation o) {
    LegendStyle s;
    s.orientation = o;
    s.margin = 0.03 * h;
    s.length = 0.4 * (o == Orientation::Horizontal ? w : h);
    s.thickness = 0.03 * h;
    s.font.sizePx = 0.028 * h;
    return s;
}

}  // namespace

TEST(NiceTicks, LinearTicksAreRoundNumbersInsideTheRange) {
    EXPECT_THAT(values(linearTicks(0, 1, 5)), ElementsAre(0, 0.2, 0.4, 0.6000000000000001, 0.8, 1));
    EXPECT_THAT(labels(linearTicks(0, 1, 5)), ElementsAre("0.0", "0.2", "0.4", "0.6", "0.8", "1.0"));
    EXPECT_THAT(values(linearTicks(-2, 6, 5)), ElementsAre(-2, 0, 2, 4, 6));
    EXPECT_THAT(labels(linearTicks(-2, 6, 5)), ElementsAre("−2", "0", "2", "4", "6"));
    EXPECT_THAT(labels(linearTicks(0.013, 0.987, 5)), ElementsAre("0.2", "0.4", "0.6", "0.8"));
    EXPECT_THAT(labels(linearTicks(1234, 98765, 5)), ElementsAre("20000", "40000", "60000", "80000"));
    // Reaching 10^5: every label scientific, with superscript exponents.
    EXPECT_THAT(labels(linearTicks(0, 2e5, 5)),
                ElementsAre("0", "5×10⁴", "1.0×10⁵", "1.5×10⁵", "2.0×10⁵"));
    EXPECT_THAT(labels(linearTicks(0.0001, 0.0009, 5)), ElementsAre("2×10⁻⁴", "4×10⁻⁴", "6×10⁻⁴", "8×10⁻⁴"));
    // Heckbert's step (0.5) would leave two ticks inside; the nearer count wins.
    EXPECT_THAT(labels(linearTicks(-0.46, 0.55, 5)), ElementsAre("−0.4", "−0.2", "0.0", "0.2", "0.4"));
    // Positions along the bar; a reversed range counts from its minimum.
    const auto r = linearTicks(6, -2, 5);
    EXPECT_EQ(r.front().value, -2);
    EXPECT_DOUBLE_EQ(r.front().t, 1.0);
    EXPECT_DOUBLE_EQ(r.back().t, 0.0);
    // A constant image: one tick in the middle.
    const auto c = linearTicks(3.5, 3.5, 5);
    ASSERT_EQ(c.size(), 1u);
    EXPECT_EQ(c[0].label, "3.50");
    EXPECT_EQ(c[0].t, 0.5);
}

TEST(NiceTicks, NiceNumbersFollowHeckbert) {
    EXPECT_EQ(niceNumber(0.974, false), 1.0);
    EXPECT_EQ(niceNumber(2.5, true), 2.0);
    EXPECT_EQ(niceNumber(3.2, true), 5.0);
    EXPECT_EQ(niceNumber(7.5, true), 10.0);
    EXPECT_EQ(niceNumber(120, false), 200.0);
}

TEST(NiceTicks, LogTicksAtDecades) {
    const auto d = logTicks(0.01, 100, 5);
    EXPECT_THAT(labels(d), ElementsAre("0.01", "0.1", "1", "10", "100"));
    for (std::size_t i = 0; i < d.size(); ++i) EXPECT_NEAR(d[i].t, 0.25 * double(i), 1e-12);
    EXPECT_THAT(labels(logTicks(1, 1e8, 5)), ElementsAre("1", "100", "10000", "10⁶", "10⁸"));
    // Fewer than three powers of ten inside: 1, 2, 5 steps.
    EXPECT_THAT(values(logTicks(2, 40, 5)), ElementsAre(2, 5, 10, 20));
    EXPECT_THAT(labels(logTicks(0.03, 1.07, 5)), ElementsAre("0.05", "0.1", "0.2", "0.5", "1"));
    EXPECT_NEAR(logTicks(2, 40, 5)[2].t, std::log10(5.0) / std::log10(20.0), 1e-12);
    try {
        logTicks(0, 10, 5);
        FAIL();
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("positive range"));
    }
}

TEST(ColorLegendLayout, TicksLieWithinHalfAPixelOfTheirValuesPosition) {
    for (const Orientation o : {Orientation::Horizontal, Orientation::Vertical})
        for (const int h : {300, 1024}) {
            const int w = 2 * h;
            const auto ticks = linearTicks(-2, 6, 5);
            const LegendLayout L = layoutLegend(ticks, styleFor(w, h, o), w, h);
            ASSERT_EQ(L.ticks.size(), 5u);
            for (const auto& p : L.ticks) {
                const double exact = o == Orientation::Horizontal ? L.bar.x + p.tick.t * L.bar.w
                                                                  : L.bar.bottom() - p.tick.t * L.bar.h;
                EXPECT_LE(std::fabs(p.position - exact), 0.5) << p.tick.label;
            }
            // Inside the image, at the margin from the bottom-right corner.
            EXPECT_NEAR(L.box.right(), w - 0.03 * h, 1.0);
            EXPECT_NEAR(L.box.bottom(), h - 0.03 * h, 1.0);
            EXPECT_GE(L.bar.x, L.box.x);
            EXPECT_LE(L.bar.right(), L.box.right());
        }
}

TEST(ColorLegendLayout, ScalesWithTheImage) {
    const auto ticks = linearTicks(0, 1, 5);
    const LegendLayout a = layoutLegend(ticks, styleFor(800, 400, Orientation::Horizontal), 800, 400);
    const LegendLayout b = layoutLegend(ticks, styleFor(3200, 1600, Orientation::Horizontal), 3200, 1600);
    // Each of the few lengths added up is rounded to whole pixels.
    EXPECT_NEAR(b.box.w, 4 * a.box.w, 12.0);
    EXPECT_NEAR(b.box.h, 4 * a.box.h, 12.0);
    EXPECT_NEAR(b.bar.w / a.bar.w, 4.0, 0.01);
    for (std::size_t i = 0; i < a.ticks.size(); ++i)
        EXPECT_NEAR(b.ticks[i].label.w / a.ticks[i].label.w, 4.0, 0.02) << i;
}

TEST(ColorLegend, DrawsTickMarksWhereTheLayoutSaysAndTheBarFromTheMap) {
    const int w = 640, h = 320;
    const auto img = blackImage(w, h);
    const auto r = drawLegend(img, {{"minimum", {Value(-2.0)}},
                                    {"maximum", {Value(6.0)}},
                                    {"box", {Value(false)}},
                                    {"outline", {Value(false)}},
                                    {"textColor", {Value(Color{1, 0, 0, 1})}},
                                    {"colormap", {Value("viridis")}}});
    const BufferPtr out = r.outputs.at("image").asImage();
    const LegendLayout L = layoutLegend(linearTicks(-2, 6, 5), styleFor(w, h, Orientation::Horizontal), w, h);
    // The row just below the bar, inside the tick marks: red exactly at the ticks.
    const int y = int(L.bar.bottom()) + 1;
    std::vector<int> columns;
    for (int x = 0; x < w; ++x)
        if (out->hostFloat("R")[std::size_t(y) * w + x] > 0.5f && out->hostFloat("G")[std::size_t(y) * w + x] == 0.0f)
            columns.push_back(x);
    ASSERT_EQ(columns.size(), 5u);  // one-pixel-wide, crisp tick lines
    for (std::size_t i = 0; i < 5; ++i) {
        EXPECT_DOUBLE_EQ(columns[i] + 0.5, L.ticks[i].position);
        EXPECT_LE(std::fabs(columns[i] + 0.5 - (L.bar.x + L.ticks[i].tick.t * L.bar.w)), 0.5);
        EXPECT_EQ(out->hostFloat("R")[std::size_t(y) * w + columns[i]], 1.0f);  // fully covered
    }
    // The bar's pixels are the map at their centre.
    const ColorMapData viridis = loadColorMap("viridis");
    const int by = int(L.bar.y + L.bar.h / 2);
    for (int x = int(L.bar.x); x < int(L.bar.right()); x += 7) {
        const Color want = viridis.sample((x + 0.5 - L.bar.x) / L.bar.w);
        const std::size_t i = std::size_t(by) * w + x;
        EXPECT_NEAR(out->hostFloat("R")[i], want.r, 2e-4) << x;
        EXPECT_NEAR(out->hostFloat("G")[i], want.g, 2e-4) << x;
        EXPECT_NEAR(out->hostFloat("B")[i], want.b, 2e-4) << x;
    }
    // Labels were drawn below the ticks (red ink in the label band), nothing above the bar.
    int ink = 0, above = 0;
    for (int yy = 0; yy < h; ++yy)
        for (int x = 0; x < w; ++x) {
            const float red = out->hostFloat("R")[std::size_t(yy) * w + x];
            const bool isRed = red > 0.1f && out->hostFloat("G")[std::size_t(yy) * w + x] == 0.0f;
            if (isRed && yy > L.bar.bottom() + L.tickLength) ++ink;
            if (isRed && yy < L.bar.y) ++above;
        }
    EXPECT_GT(ink, 50);
    EXPECT_EQ(above, 0);
    // Outside the box the image is untouched, bit for bit.
    for (int x = 0; x < int(L.box.x); ++x) EXPECT_EQ(out->hostFloat("R")[std::size_t(h / 2) * w + x], 0.0f);
}

TEST(ColorLegend, VerticalLogLegendFollowsColorMappingsOutputs) {
    // ColorMapping on a log field, its four outputs into the legend.
    const auto field = test::makeImage(64, 32, {"density"}, [](int x, int, int) { return std::pow(10.0f, -2.0f + 4.0f * x / 63.0f); });
    auto cm = test::pluginRegistry().createFilter("ColorMapping");
    FilterRunOptions o;
    auto mapped = runFilter(*cm, {{"image", {Value(BufferPtr(field))}}, {"scale", {Value("log")}},
                                  {"colormap", {Value("plasma")}}}, o);
    const auto r = drawLegend(mapped.outputs.at("image").asImage(),
                              {{"minimum", {mapped.outputs.at("usedMinimum")}},
                               {"maximum", {mapped.outputs.at("usedMaximum")}},
                               {"scale", {mapped.outputs.at("usedScale")}},
                               {"colormap", {mapped.outputs.at("usedColormap")}},
                               {"orientation", {Value("vertical")}},
                               {"anchor", {Value("topLeft")}},
                               {"fontSize", {Value(0.08)}},
                               {"length", {Value(0.8)}},
                               {"thickness", {Value(0.08)}}});
    const BufferPtr out = r.outputs.at("image").asImage();
    ASSERT_TRUE(out);
    EXPECT_TRUE(r.warnings.empty());
    // The bar runs upwards: plasma's start colour at the bottom, its end at the top.
    LegendStyle s = styleFor(64, 32, Orientation::Vertical);
    s.anchor = Anchor::TopLeft;
    s.font.sizePx = 0.08 * 32;
    s.length = 0.8 * 32;
    s.thickness = 0.08 * 32;
    const LegendLayout L = layoutLegend(logTicks(0.01, 100, 5), s, 64, 32);
    const ColorMapData plasma = loadColorMap("plasma");
    const int x = int(L.bar.x + L.bar.w / 2);
    const std::size_t bottom = std::size_t(L.bar.bottom() - 1) * 64 + x, top = std::size_t(L.bar.y) * 64 + x;
    EXPECT_NEAR(out->hostFloat("R")[bottom], plasma.sample(0.5 / L.bar.h).r, 1e-3);
    EXPECT_NEAR(out->hostFloat("R")[top], plasma.sample(1 - 0.5 / L.bar.h).r, 1e-3);
}

TEST(ColorLegend, NoRangeDrawsABarWithoutTicksAndWarns) {
    const auto r = drawLegend(blackImage(200, 100), {{"minimum", {Value(std::numeric_limits<double>::quiet_NaN())}}});
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_THAT(r.warnings[0], HasSubstr("without tick labels"));
    const BufferPtr out = r.outputs.at("image").asImage();
    for (const auto& c : out->channels())
        for (std::size_t i = 0; i < out->pixelCount(); ++i) ASSERT_TRUE(std::isfinite(out->hostFloat(c.name)[i]));
}

TEST(ColorLegend, ErrorsAreClear) {
    try {
        drawLegend(blackImage(200, 100), {{"scale", {Value("log")}}, {"minimum", {Value(-1.0)}}});
        FAIL();
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("log-scale legend needs a positive range"));
    }
    try {
        drawLegend(blackImage(200, 100), {{"labelFormat", {Value(".2q")}}});
        FAIL();
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("labelFormat '.2q'"));
    }
}

TEST(ColorLegend, CrowdedLabelsGiveFewerEvenlySpacedTicks) {
    // A short bar with large labels: 5 requested ticks of [-0.5, 0.55] cannot
    // all be labelled; the legend asks for fewer instead of leaving gaps.
    const int w = 768, h = 768;
    const auto r = drawLegend(blackImage(w, h), {{"minimum", {Value(-0.5)}},
                                                 {"maximum", {Value(0.55)}},
                                                 {"length", {Value(0.3)}},
                                                 {"fontSize", {Value(0.05)}},
                                                 {"box", {Value(false)}},
                                                 {"outline", {Value(false)}},
                                                 {"textColor", {Value(Color{1, 0, 0, 1})}}});
    const BufferPtr out = r.outputs.at("image").asImage();
    // Count the tick marks in the row below the bar: find the bar's lowest row first.
    int barBottom = -1;
    for (int y = h - 1; y >= 0 && barBottom < 0; --y)
        for (int x = 0; x < w; ++x)
            if (out->hostFloat("G")[std::size_t(y) * w + x] > 0.05f) {  // the map's pixels have green
                barBottom = y;
                break;
            }
    ASSERT_GT(barBottom, 0);
    // Tick lines are several pixels wide at this size: one tick = one run of columns.
    std::vector<double> centres;
    for (int x = 0; x < w; ++x) {
        if (out->hostFloat("R")[std::size_t(barBottom + 1) * w + x] != 1.0f) continue;
        const int start = x;
        while (x + 1 < w && out->hostFloat("R")[std::size_t(barBottom + 1) * w + x + 1] == 1.0f) ++x;
        centres.push_back(0.5 * (start + x));
    }
    ASSERT_GE(centres.size(), 2u);
    ASSERT_LT(centres.size(), 5u);
    for (std::size_t i = 2; i < centres.size(); ++i)
        EXPECT_NEAR(centres[i] - centres[i - 1], centres[1] - centres[0], 1) << "evenly spaced";
}
