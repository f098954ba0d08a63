// Annotation: placeholders filled from the row (known text gives the same
// pixels as typing it), anchors put the ink where they say, multi-line text,
// the box, untouched pixels, the row arriving from a CinemaReader in a graph,
// clear errors.
#include "annotation.h"
#include "annotation_text.h"
#include "test_support.h"

#include <darkroom/error.h>
#include <darkroom/data/cinema/writer.h>
#include <darkroom/core/evaluator.h>
#include <darkroom/core/graph.h>
#include <darkroom/core/run_filter.h>
#include <darkroom/srgb.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

using namespace darkroom;
using ::testing::HasSubstr;

namespace {

using Inputs = std::map<std::string, std::vector<Value>>;

BufferPtr annotate(const BufferPtr& image, Inputs extra) {
    auto f = test::pluginRegistry().createFilter("Annotation");
    extra["image"] = {Value(image)};
    FilterRunOptions o;
    o.threads = 2;
    return runFilter(*f, extra, o).outputs.at("image").asImage();
}

std::shared_ptr<WritableBuffer> grey(int w, int h, float v = 0.2f) {
    return test::makeImage(w, h, {"R", "G", "B"}, [=](int, int, int) { return v; });
}

// Bounding box of pixels that changed.
struct Ink {
    int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
    int count = 0;
};
Ink inkOf(const Buffer& before, const Buffer& after) {
    Ink k;
    for (int y = 0; y < after.height(); ++y)
        for (int x = 0; x < after.width(); ++x) {
            const std::size_t i = std::size_t(y) * after.width() + x;
            if (before.hostFloat("R")[i] == after.hostFloat("R")[i]) continue;
            k.x0 = std::min(k.x0, x);
            k.y0 = std::min(k.y0, y);
            k.x1 = std::max(k.x1, x);
            k.y1 = std::max(k.y1, y);
            ++k.count;
        }
    return k;
}

}  // namespace

TEST(Annotation, ExpandsPlaceholdersAndLineBreaks) {
    using annotation::expandText;
    EXPECT_EQ(expandText("t = {time:.2f} s\\nphi = {phi}°", parseRow("time=0.125, phi=30"), false), "t = 0.12 s\nphi = 30°");
    EXPECT_EQ(expandText("no row needed {{here}}", parseRow(""), false), "no row needed {here}");
    EXPECT_EQ(expandText("two\nlines", parseRow(""), false), "two\nlines");
    EXPECT_EQ(expandText("{{{phi}}} {{x}}", parseRow("phi=-30"), true), "{-30} {x}");
    // Markup: values are escaped, the template is not; a value's own "\n" stays as written.
    EXPECT_EQ(expandText("<i>{a}</i>\\n{b:>6}|{c:.2}", parseRow("a=R&D, b=<x>, c=\"'\"\"x\""), true),
              "<i>R&amp;D</i>\n   &lt;x&gt;|&apos;&quot;");
    EXPECT_EQ(expandText("{a}", parseRow("a=x\\ny"), true), "x\\ny");
}

TEST(Annotation, FilledPlaceholdersDrawExactlyTheTypedText) {
    const auto img = grey(400, 200);
    const BufferPtr viaRow = annotate(img, {{"text", {Value("t = {time:.1f} s, phi {phi}")}},
                                            {"row", {Value("time=2.25, phi=-30, FILE=\"/x/y.exr\"")}},
                                            {"color", {Value(Color{1, 1, 1, 1})}}});
    const BufferPtr typed = annotate(img, {{"text", {Value("t = 2.2 s, phi -30")}}, {"color", {Value(Color{1, 1, 1, 1})}}});
    EXPECT_TRUE(identical(*viaRow, *typed));
    EXPECT_GT(inkOf(*img, *typed).count, 100);
}

TEST(Annotation, AnchorsPlaceTheTextAtTheirCornerWithTheMargin) {
    const int w = 600, h = 300;
    const auto img = grey(w, h);
    const double margin = 0.05 * h, pad = 0.4 * 0.06 * h;
    for (const char* anchor : {"topLeft", "topRight", "bottomLeft", "bottomRight", "center", "top", "bottom"}) {
        const BufferPtr out = annotate(img, {{"text", {Value("Anchored\nText")}}, {"anchor", {Value(anchor)}},
                                             {"margin", {Value(0.05)}}, {"fontSize", {Value(0.06)}},
                                             {"color", {Value(Color{1, 1, 1, 1})}}});
        const Ink k = inkOf(*img, *out);
        ASSERT_GT(k.count, 50) << anchor;
        const std::string a = anchor;
        // Ink lies inside the padded box, a few pixels from the anchored edges.
        if (a.find("Left") != std::string::npos) {
            EXPECT_NEAR(k.x0, margin + pad, 4) << anchor;
        }
        if (a.find("Right") != std::string::npos) {
            EXPECT_NEAR(k.x1 + 1, w - margin - pad, 4) << anchor;
        }
        if (a.rfind("top", 0) == 0) {
            EXPECT_NEAR(k.y0, margin + pad, 0.35 * 0.06 * h) << anchor;
        }
        if (a.rfind("bottom", 0) == 0) {
            EXPECT_NEAR(k.y1 + 1, h - margin - pad, 0.35 * 0.06 * h) << anchor;
        }
        if (a == "center" || a == "top" || a == "bottom") {
            EXPECT_NEAR((k.x0 + k.x1 + 1) / 2.0, w / 2.0, 3) << anchor;
        }
        if (a == "center") {
            EXPECT_NEAR((k.y0 + k.y1 + 1) / 2.0, h / 2.0, 0.2 * 0.06 * h) << anchor;
        }
    }
    // An offset moves the block by exactly that many pixels.
    const BufferPtr base = annotate(img, {{"text", {Value("Offset")}}, {"color", {Value(Color{1, 1, 1, 1})}}});
    const BufferPtr moved = annotate(img, {{"text", {Value("Offset")}}, {"offsetX", {Value(0.1)}},
                                           {"offsetY", {Value(0.05)}}, {"color", {Value(Color{1, 1, 1, 1})}}});
    const Ink a = inkOf(*img, *base), b = inkOf(*img, *moved);
    EXPECT_EQ(b.x0 - a.x0, 30);
    EXPECT_EQ(b.y0 - a.y0, 15);
    EXPECT_EQ(a.count, b.count);
}

TEST(Annotation, SecondLineDoublesTheHeight) {
    const auto img = grey(400, 300);
    const Inputs common{{"fontSize", {Value(0.08)}}, {"color", {Value(Color{1, 1, 1, 1})}}};
    Inputs one = common, two = common;
    one["text"] = {Value("Hg")};
    two["text"] = {Value("Hg\\nHg")};
    const Ink a = inkOf(*img, *annotate(img, one)), b = inkOf(*img, *annotate(img, two));
    const double lineHeight = b.y1 - a.y1;
    EXPECT_NEAR(lineHeight, 1.17 * 0.08 * 300, 3.0);  // DejaVu Sans line spacing: 1.164 em
    EXPECT_EQ(b.count, 2 * a.count);
}

TEST(Annotation, BoxIsPaintedAndPixelsOutsideItAreUntouched) {
    const auto img = grey(300, 150, 0.5f);
    const BufferPtr out = annotate(img, {{"text", {Value("Box")}}, {"box", {Value(true)}},
                                         {"boxColor", {Value(Color{0, 0, 0, 0.5f})}}, {"margin", {Value(0.1)}}});
    // Just inside the box's top-left corner (past its rounding): black at half
    // opacity over 0.5 linear, blended on sRGB values.
    const int inside = int(0.1 * 150) + int(0.3 * 0.04 * 150) + 1;
    const float want = srgbToLinear(0.5f * linearToSrgb(0.5f));
    EXPECT_NEAR(out->hostFloat("R")[std::size_t(inside) * 300 + inside], want, 2e-3);
    EXPECT_EQ(out->hostFloat("R")[std::size_t(5) * 300 + 5], 0.5f);
    EXPECT_EQ(out->hostFloat("R")[std::size_t(149) * 300 + 299], 0.5f);
}

TEST(Annotation, RowComesFromACinemaReaderInAGraph) {
    test::TempDir dir;
    {
        CinemaWriter w(dir.file("t.cdb"), {"time"});
        auto img = test::makeImage(200, 100, {"R", "G", "B"}, [](int, int, int) { return 0.1f; });
        w.addEntry({{"time", CinemaValue(1.5)}}, *img);
        w.addEntry({{"time", CinemaValue(2.5)}}, *img);
        w.finish();
    }
    Graph g(test::pluginRegistry());
    g.addNode("read", "CinemaReader");
    g.setParameter("read", "database", Value(dir.file("t.cdb")));
    g.addNode("label", "Annotation");
    g.setParameter("label", "text", Value("time {time}"));
    g.setParameter("label", "color", Value(Color{1, 1, 1, 1}));
    g.connect({"read", "image"}, {"label", "image"});
    g.connect({"read", "row"}, {"label", "row"});
    Evaluator ev;
    // The same picture typed by hand; the reader's image also names its product.
    const auto typed = [&](const std::string& text, const std::string& product) {
        auto img = test::makeImage(200, 100, {"R", "G", "B"}, [](int, int, int) { return 0.1f; });
        img->metadata().attributes["source"] = dir.file("t.cdb/" + product);
        return annotate(img, {{"text", {Value(text)}}, {"color", {Value(Color{1, 1, 1, 1})}}});
    };
    g.setParameter("read", "parameters", Value("time=1.5"));
    const BufferPtr first = ev.evaluateImage(g, "label", "image");
    EXPECT_TRUE(identical(*first, *typed("time 1.5", "time=1.5.exr")));
    g.setParameter("read", "parameters", Value("time=2.5"));
    EXPECT_TRUE(identical(*ev.evaluateImage(g, "label", "image"), *typed("time 2.5", "time=2.5.exr")));
}

TEST(Annotation, ErrorsNameWhatIsMissing) {
    const auto img = grey(100, 50);
    auto message = [&](Inputs in) {
        try {
            annotate(img, in);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_THAT(message({{"text", {Value("{time}")}}}), HasSubstr("'row' is empty"));
    EXPECT_THAT(message({{"text", {Value("{theta}")}}, {"row", {Value("time=1, phi=2")}}}),
                HasSubstr("placeholder {theta} names no column of the row (columns: time, phi)"));
    EXPECT_THAT(message({{"text", {Value("<b>bold")}}, {"markup", {Value(true)}}}), HasSubstr("Pango markup"));
}
