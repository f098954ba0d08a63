#pragma once
// Text and simple shapes for the overlay nodes (ColorLegend, Annotation):
// shapes and glyphs are drawn as coverage masks with cairo and pango (Debian's
// libcairo2 and libpango1.0, font found through fontconfig: DejaVu Sans from
// fonts-dejavu-core by default), then painted over the linear image. Neither
// cairo nor pango appears in this header.
//
// Text is laid out at the image's own resolution (sizes are pixels), without
// hinting, so a label drawn at twice the size is the same shape twice as
// large: crisp at any resolution, and placed identically whatever the size.
#include <darkroom/buffer.h>
#include <darkroom/value.h>

#include <memory>
#include <string>

namespace darkroom {
class Context;
}

namespace darkroom::text {

struct Font {
    std::string family = "DejaVu Sans";
    double sizePx = 16;  // the em size, in pixels
    bool bold = false;
};

enum class Align { Left, Center, Right };

// The logical box pango gives a block of (multi-line) text: width, height
// (line spacing included) and the first line's baseline, from the top.
struct TextBox {
    double width = 0, height = 0, baseline = 0;
};

// Laid out as Mask::text draws it. `markup`: Pango markup (<sup>, <b>, ...)
// instead of plain text.
TextBox measure(const std::string& text, const Font& font, Align align = Align::Left, bool markup = false);

// The font family fontconfig actually picked for `family` (to tell the user
// when the one asked for is not installed).
std::string resolvedFamily(const std::string& family);

// Coverage in [0, 1] per pixel, drawn with cairo's grey antialiasing.
class Mask {
public:
    Mask(int width, int height);  // all zero
    ~Mask();
    Mask(const Mask&) = delete;
    Mask& operator=(const Mask&) = delete;

    int width() const;
    int height() const;

    // `text` with the top-left corner of its logical box at (x, y); lines
    // aligned within the box as `align` says.
    void text(double x, double y, const std::string& text, const Font& font, Align align = Align::Left,
              bool markup = false);
    // A straight line of the given width with butt ends.
    void line(double x0, double y0, double x1, double y1, double width);
    // A filled rectangle, corners rounded by `radius` pixels.
    void rectangle(double x, double y, double w, double h, double radius = 0);
    // The outline of a rectangle, centred on its edges.
    void frame(double x, double y, double w, double h, double lineWidth);

    float coverage(int x, int y) const;
    // The 8-bit coverage, `stride` bytes per row (all drawing finished).
    const unsigned char* pixels(int& stride) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// The colour planes an overlay is painted on (A may be null: opaque).
struct RgbaPlanes {
    float* r = nullptr;
    float* g = nullptr;
    float* b = nullptr;
    float* a = nullptr;
    int width = 0, height = 0;
};

// An overlay node's output: `in` with fresh copies of R, G, B (and A when
// present) to paint on; every other channel shared. Throws darkroom::Error
// naming the missing channel when `in` has no float R, G or B.
struct Overlay {
    std::shared_ptr<WritableBuffer> buffer;
    RgbaPlanes planes;
};
Overlay beginOverlay(Context& ctx, const BufferPtr& in);

// Paints linear `color` (its alpha scales the coverage) through `mask`, the
// mask's top-left corner at image pixel (ox, oy); the part outside the image
// is clipped. Straight-alpha "over", blended on sRGB-encoded values as 8-bit
// renderers (cairo, browsers, ParaView's text) blend text, so glyphs have the
// weight they have in any other program; pixels the mask does not touch are
// left exactly as they were.
void paint(const Mask& mask, int ox, int oy, Color color, const RgbaPlanes& image);

}  // namespace darkroom::text
