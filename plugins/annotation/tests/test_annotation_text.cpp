// Annotation's text from data (issue 26): values substituted into markup are
// text (escaped, the template keeps its markup), and what a node may produce
// is bounded: format widths and precisions, the length of a value and of the
// text drawn — refused quickly, naming the node and the limit.
#include "test_support.h"

#include <darkroom/error.h>
#include <darkroom/core/run_filter.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>

using namespace darkroom;
using ::testing::HasSubstr;

namespace {

using Inputs = std::map<std::string, std::vector<Value>>;

BufferPtr annotate(Inputs extra) {
    auto f = test::pluginRegistry().createFilter("Annotation");
    extra["image"] = {Value(BufferPtr(test::makeImage(400, 100, {"R", "G", "B"}, [](int, int, int) { return 0.2f; })))};
    extra["color"] = {Value(Color{1, 1, 1, 1})};
    FilterRunOptions o;
    o.threads = 2;
    return runFilter(*f, extra, o).outputs.at("image").asImage();
}

std::string errorOf(Inputs in) {
    try {
        annotate(std::move(in));
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

// Runs `in` and checks it is refused within seconds, naming the node and `limit`.
void expectRefused(Inputs in, const std::string& limit) {
    const auto start = std::chrono::steady_clock::now();
    const std::string e = errorOf(std::move(in));
    EXPECT_THAT(e, HasSubstr("node 'runFilter'"));
    EXPECT_THAT(e, HasSubstr(limit));
    EXPECT_LT(e.size(), 2000u);  // long values are not echoed
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
}

}  // namespace

TEST(AnnotationText, ValuesFromDataAreEscapedInMarkup) {
    // R&D once stopped the run ("not valid Pango markup"); a <span> value was
    // drawn as markup. Both are text: the same pixels as the escaped template.
    const BufferPtr viaRow = annotate({{"text", {Value("<b>{team}</b> {note}")}},
                                       {"row", {Value("team=R&D, note=<span foreground='red'>x</span>")}},
                                       {"markup", {Value(true)}}});
    const BufferPtr typed =
        annotate({{"text", {Value("<b>R&amp;D</b> &lt;span foreground=&apos;red&apos;&gt;x&lt;/span&gt;")}},
                  {"markup", {Value(true)}}});
    EXPECT_TRUE(identical(*viaRow, *typed));
    // Without markup the value is drawn as written.
    const BufferPtr plain = annotate({{"text", {Value("{team}")}}, {"row", {Value("team=R&D")}}});
    EXPECT_TRUE(identical(*plain, *annotate({{"text", {Value("R&D")}}})));
}

TEST(AnnotationText, FormatWidthsAndPrecisionsAreBounded) {
    expectRefused({{"text", {Value("{phi:>100000}")}}, {"row", {Value("phi=30")}}}, "at most 1000");
    expectRefused({{"text", {Value("{phi:.100000f}")}}, {"row", {Value("phi=30")}}}, "at most 1000");
    expectRefused({{"text", {Value("{name:x^99999999999999999999999}")}}, {"row", {Value("name=a")}}}, "at most 1000");
    // At the limit: formatted (and clipped at the image edge).
    EXPECT_TRUE(annotate({{"text", {Value("{phi:>1000}")}}, {"row", {Value("phi=30")}}}));
}

TEST(AnnotationText, TextAndValuesAreBounded) {
    // A 1 MB cell of data: refused before it is laid out.
    expectRefused({{"text", {Value("{note}")}}, {"row", {Value("note=" + std::string(1 << 20, 'x'))}}},
                  "at most 65536 bytes");
    // Many placeholders, each within the limits, that add up past it.
    std::string many;
    for (int i = 0; i < 100; ++i) many += "{phi:>1000}";
    expectRefused({{"text", {Value(many)}}, {"row", {Value("phi=30")}}}, "at most 65536 bytes");
    // Typed text past the limit.
    expectRefused({{"text", {Value(std::string(70000, 'x'))}}}, "at most 65536 bytes");
}
