// ColorLegend's text (issue 26): negative ticks in scientific notation are
// labelled (their label was once parsed back with std::stod and failed on the
// typeset minus), every finite range gives ticks inside it with labels, and
// what a node may write is bounded: format widths and precisions, titles.
#include "nice_ticks.h"
#include "test_support.h"

#include <darkroom/error.h>
#include <darkroom/core/run_filter.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <limits>

using namespace darkroom;
using namespace darkroom::legend;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

namespace {

std::vector<std::string> labels(const std::vector<Tick>& t) {
    std::vector<std::string> v;
    for (const auto& x : t) v.push_back(x.label);
    return v;
}

using Inputs = std::map<std::string, std::vector<Value>>;

FilterRunResult drawLegend(Inputs extra) {
    auto f = test::pluginRegistry().createFilter("ColorLegend");
    extra["image"] = {Value(BufferPtr(
        test::makeImage(400, 200, {"R", "G", "B"}, [](int, int, int) { return 0.0f; })))};
    FilterRunOptions o;
    o.threads = 2;
    return runFilter(*f, extra, o);
}

std::string errorOf(Inputs in) {
    try {
        drawLegend(std::move(in));
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

const std::string kMinus = "\u2212";

}  // namespace

TEST(LegendText, NegativeScientificTicksAreLabelled) {
    EXPECT_THAT(labels(linearTicks(-0.001, 0.001, 5)),
                ElementsAre("−1.0×10⁻³", "−5×10⁻⁴", "0", "5×10⁻⁴", "1.0×10⁻³"));
    EXPECT_THAT(labels(linearTicks(-2e5, 2e5, 5)), ElementsAre("−2×10⁵", "−10⁵", "0", "10⁵", "2×10⁵"));
    EXPECT_EQ(formatTickLabel(-9.9e-4, 1e-5, true), "−9.9×10⁻⁴");
    // A mantissa rounding up to ten moves to the next decade, sign kept, with
    // the decimals the step needs there.
    EXPECT_EQ(formatTickLabel(-9.996e-4, 1e-5, true), "−1.00×10⁻³");
    EXPECT_EQ(formatTickLabel(9.99999999999e-4, 1e-5, true), "1.00×10⁻³");
    // As many digits as the step needs, exactly (not through a divided mantissa).
    EXPECT_EQ(formatTickLabel(1e15 + 0.5, 0.5, true), "1.0000000000000005×10¹⁵");
}

TEST(LegendText, EveryFiniteRangeGivesLabelledTicksInsideIt) {
    // Symmetric ranges at every magnitude: labels mirror, the negative ones
    // with a typeset minus in front of the positive label.
    for (int k = -300; k <= 300; k += 7)
        for (const double m : {1.0, 2.0, 3.7}) {
            const double a = m * std::pow(10.0, k);
            const auto ticks = linearTicks(-a, a, 5);
            ASSERT_GE(ticks.size(), 2u) << a;
            for (std::size_t i = 0; i < ticks.size(); ++i) {
                const Tick& t = ticks[i];
                const Tick& mirror = ticks[ticks.size() - 1 - i];
                ASSERT_FALSE(t.label.empty()) << a;
                EXPECT_EQ(t.label.find("inf"), std::string::npos) << t.label;
                EXPECT_EQ(t.label.find("nan"), std::string::npos) << t.label;
                if (t.value < 0) {
                    EXPECT_EQ(t.label, kMinus + mirror.label) << a;
                }
            }
        }
    // As wide as doubles go, as narrow as they go, and everything between.
    const double big = std::numeric_limits<double>::max(), tiny = std::numeric_limits<double>::denorm_min();
    for (const auto& [lo, hi] : std::vector<std::pair<double, double>>{
             {-big, big}, {0, big}, {-big, -big / 3}, {0, tiny}, {-tiny, tiny}, {1e-310, 3e-310},
             {1.0, std::nextafter(1.0, 2.0)}, {1e300, std::nextafter(1e300, 2e300)}, {-1e30, 1e30}}) {
        const auto ticks = linearTicks(lo, hi, 5);
        ASSERT_FALSE(ticks.empty()) << lo << " " << hi;
        for (const Tick& t : ticks) {
            // Within the documented 1e-9-step tolerance (denormal steps are inexact).
            EXPECT_GE(t.value, lo - std::fabs(lo) * 1e-12) << lo << " " << hi;
            EXPECT_LE(t.value, hi + std::fabs(hi) * 1e-12) << lo << " " << hi;
            EXPECT_GE(t.t, -1e-9);
            EXPECT_LE(t.t, 1 + 1e-9);
            EXPECT_FALSE(t.label.empty());
            EXPECT_EQ(t.label.find("inf"), std::string::npos) << t.label;
        }
    }
}

// Found by the fuzz harness (tests/fuzz/harnesses/legend.cpp): ten trillion
// steps from zero, k × step rounds past the range's end — the last tick of
// [1e300, 1.0000000000001e300] lay at t = 1.0015, beyond the bar.
TEST(LegendText, TicksFarFromZeroStayOnTheBar) {
    for (const auto& [lo, hi] : std::vector<std::pair<double, double>>{
             {1e300, 1.0000000000001e300}, {-1.0000000000001e300, -1e300}, {1e20, 1e20 + 1e7}}) {
        for (const int count : {2, 5, 7}) {
            const auto ticks = linearTicks(lo, hi, count);
            ASSERT_FALSE(ticks.empty());
            for (const Tick& t : ticks) {
                EXPECT_GE(t.t, -1e-9) << lo << " " << count << " " << t.label;
                EXPECT_LE(t.t, 1 + 1e-9) << lo << " " << count << " " << t.label;
            }
        }
    }
}

TEST(LegendText, TheNodeDrawsRangesWithNegativeScientificTicks) {
    for (const auto& [lo, hi] : std::vector<std::pair<double, double>>{{-0.001, 0.001}, {-2e5, 2e5}, {-1e30, 1e30}}) {
        const auto r = drawLegend({{"minimum", {Value(lo)}}, {"maximum", {Value(hi)}}});
        EXPECT_TRUE(r.outputs.at("image").asImage()) << lo;
    }
}

TEST(LegendText, FormatWidthsAndPrecisionsAreBounded) {
    // Far above text::kMaxFormatWidth: refused before any text is made.
    for (const char* spec : {">100000.2f", ".100000f", "0100000e", ">99999999999999999999999f"}) {
        const auto start = std::chrono::steady_clock::now();
        const std::string e = errorOf({{"labelFormat", {Value(spec)}}});
        EXPECT_THAT(e, HasSubstr("labelFormat")) << spec;
        EXPECT_THAT(e, HasSubstr("at most 1000")) << spec;
        EXPECT_THAT(e, HasSubstr("node 'runFilter'")) << spec;
        EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5)) << spec;
    }
    // At the limit (text::kMaxFormatWidth) it formats; the labels do not fit and are left out.
    EXPECT_TRUE(drawLegend({{"labelFormat", {Value(">1000.2f")}}}).outputs.at("image").asImage());
    // Braces would let the specification write text of its own.
    EXPECT_THAT(errorOf({{"labelFormat", {Value("}x}")}}}), HasSubstr("braces"));
}

TEST(LegendText, TitlesLongerThanTheTextLimitAreRefused) {
    const std::string title(64 * 1024 + 1, 'x');  // text::kMaxTextBytes + 1
    const std::string e = errorOf({{"title", {Value(title)}}});
    EXPECT_THAT(e, HasSubstr("node 'runFilter'"));
    EXPECT_THAT(e, HasSubstr("at most 65536 bytes"));
    EXPECT_LT(e.size(), 1000u);  // the title is not echoed
}
