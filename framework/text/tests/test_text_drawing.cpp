// The overlay drawing library: text metrics scale with the size, glyphs stay
// inside their logical box, the font asked for is the font used, shapes cover
// exactly their area, and painting blends as 8-bit renderers do.
#include <darkroom/text/text_drawing.h>
#include <darkroom/text/text_limits.h>

#include <darkroom/error.h>
#include <darkroom/srgb.h>

#include <gtest/gtest.h>

#include <vector>

using namespace darkroom;
using namespace darkroom::text;

TEST(TextDrawing, DejaVuSansIsInstalledAndUsed) {
    EXPECT_EQ(resolvedFamily("DejaVu Sans"), "DejaVu Sans");
}

TEST(TextDrawing, MetricsScaleLinearlyWithTheFontSize) {
    Font small{"DejaVu Sans", 12};
    Font large{"DejaVu Sans", 48};
    const TextBox a = measure("Height (m) 0.25", small);
    const TextBox b = measure("Height (m) 0.25", large);
    ASSERT_GT(a.width, 10);
    EXPECT_NEAR(b.width / a.width, 4.0, 0.01);
    EXPECT_NEAR(b.height / a.height, 4.0, 0.01);
    EXPECT_NEAR(b.baseline / a.baseline, 4.0, 0.01);
    // Two lines are twice as tall as one, and as wide as the wider.
    const TextBox two = measure("Height (m)\n0.25", large);
    EXPECT_NEAR(two.height, 2 * b.height, 0.5);
    EXPECT_NEAR(two.width, measure("Height (m)", large).width, 1e-6);
}

TEST(TextDrawing, GlyphsLieInsideTheirLogicalBox) {
    const Font font{"DejaVu Sans", 30};
    const std::string text = "Tg 1.5×10⁻³\nsecond line";
    const TextBox box = measure(text, font);
    Mask mask(400, 200);
    const double x = 20.25, y = 30.5;
    mask.text(x, y, text, font);
    double inked = 0;
    for (int py = 0; py < mask.height(); ++py)
        for (int px = 0; px < mask.width(); ++px) {
            const float c = mask.coverage(px, py);
            inked += c;
            // Antialiasing may bleed into the next pixel outside the box.
            if (c > 0) {
                EXPECT_GE(px + 2, x) << px << "," << py;
                EXPECT_LE(px, x + box.width + 1) << px << "," << py;
                EXPECT_GE(py + 2, y) << px << "," << py;
                EXPECT_LE(py, y + box.height + 1) << px << "," << py;
            }
        }
    EXPECT_GT(inked, 200.0);  // something was drawn
}

TEST(TextDrawing, RectanglesCoverExactlyTheirPixels) {
    Mask mask(10, 8);
    mask.rectangle(2, 3, 4, 2);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 10; ++x)
            EXPECT_EQ(mask.coverage(x, y), (x >= 2 && x < 6 && y >= 3 && y < 5) ? 1.0f : 0.0f) << x << "," << y;
    // A half-pixel offset covers the edge pixels by half.
    Mask half(4, 1);
    half.rectangle(0.5, 0, 2, 1);
    EXPECT_NEAR(half.coverage(0, 0), 0.5f, 1.0f / 255);
    EXPECT_EQ(half.coverage(1, 0), 1.0f);
    EXPECT_NEAR(half.coverage(2, 0), 0.5f, 1.0f / 255);
}

TEST(TextDrawing, PaintBlendsOnSrgbValuesAndLeavesUntouchedPixelsAlone) {
    const int w = 4, h = 1;
    std::vector<float> r(w, 1.0f), g(w, 1.0f), b(w, 1.0f), a(w, 0.25f);
    r[3] = 0.3f;  // a pixel the mask does not touch keeps its exact bits
    Mask mask(w, h);
    mask.rectangle(0, 0, 1, 1);     // full coverage
    mask.rectangle(1.5, 0, 1, 1);   // half of pixel 1 and half of pixel 2
    paint(mask, 0, 0, Color{0, 0, 0, 1}, RgbaPlanes{r.data(), g.data(), b.data(), a.data(), w, h});
    EXPECT_EQ(r[0], 0.0f);
    EXPECT_EQ(a[0], 1.0f);
    // Half-covered black over white with alpha 0.25: a = 0.5 + 0.25 * 0.5,
    // colour (sRGB) = (0 * 0.5 + 1 * 0.25 * 0.5) / a.
    const float k = 128.0f / 255.0f;
    const float alpha = k + 0.25f * (1 - k);
    EXPECT_NEAR(a[1], alpha, 1e-6);
    EXPECT_NEAR(r[1], srgbToLinear(0.25f * (1 - k) / alpha), 1e-5);
    EXPECT_EQ(r[3], 0.3f);
    EXPECT_EQ(a[3], 0.25f);
}

TEST(TextDrawing, MalformedMarkupIsAClearError) {
    try {
        measure("<sup>2", Font{}, Align::Left, true);
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("not valid Pango markup"), std::string::npos);
    }
}

// The limits every overlay node shares (text_limits.h, issue 26): format
// numbers at most 1000, text at most 64 KiB — measure and draw refuse longer
// text for any caller — and markup escaping of values.
TEST(TextLimits, FormatNumbersTextLengthAndMarkupEscaping) {
    EXPECT_NO_THROW(checkFormatSpec(">1000.1000f", "spec"));
    EXPECT_NO_THROW(checkFormatSpec("9>+08.3e", "spec"));
    for (const char* spec : {">1001", ".1001f", "0001001", "x^99999999999999999999999999999999"}) {
        try {
            checkFormatSpec(spec, "spec");
            ADD_FAILURE() << spec;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("at most 1000"), std::string::npos) << e.what();
        }
    }
    EXPECT_NO_THROW(checkTextLength(std::string(kMaxTextBytes, 'x'), "text"));
    const std::string tooLong(kMaxTextBytes + 1, 'x');
    EXPECT_THROW(measure(tooLong, Font{}), InputError);
    Mask mask(10, 10);
    EXPECT_THROW(mask.text(0, 0, tooLong, Font{}), InputError);
    EXPECT_EQ(escapeMarkup("R&D <b>'x'\"y\"</b> é"), "R&amp;D &lt;b&gt;&apos;x&apos;&quot;y&quot;&lt;/b&gt; é");
}
