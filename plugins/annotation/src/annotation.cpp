#include "annotation.h"

#include "annotation_text.h"
#include <darkroom/text/text_drawing.h>

#include <darkroom/error.h>

#include <algorithm>
#include <cmath>

namespace darkroom {

void Annotation::execute(Context& ctx) {
    const BufferPtr in = ctx.get(image_);
    const int w = in->width(), h = in->height();
    const bool markup = ctx.get(markup_);
    const std::string content = annotation::expandText(ctx.get(text_), ctx.get(row_), markup);
    if (content.empty()) {
        ctx.set(result_, in);  // nothing to draw: the input itself
        return;
    }
    const Anchor anchor = ctx.get(anchor_);
    Align align = ctx.get(align_);
    const bool left = anchor == Anchor::TopLeft || anchor == Anchor::Left || anchor == Anchor::BottomLeft;
    const bool right = anchor == Anchor::TopRight || anchor == Anchor::Right || anchor == Anchor::BottomRight;
    const bool top = anchor == Anchor::TopLeft || anchor == Anchor::Top || anchor == Anchor::TopRight;
    const bool bottom = anchor == Anchor::BottomLeft || anchor == Anchor::Bottom || anchor == Anchor::BottomRight;
    if (align == Align::Auto) align = left ? Align::Left : right ? Align::Right : Align::Center;

    text::Font font;
    font.family = ctx.get(font_);
    font.sizePx = ctx.get(fontSize_) * h;
    font.bold = ctx.get(bold_);
    const text::Align textAlign = align == Align::Left     ? text::Align::Left
                                  : align == Align::Center ? text::Align::Center
                                                           : text::Align::Right;
    const text::TextBox box = text::measure(content, font, textAlign, markup);
    const double pad = ctx.get(padding_) * font.sizePx;
    const double boxW = std::ceil(box.width + 2 * pad), boxH = std::ceil(box.height + 2 * pad);
    const double margin = ctx.get(margin_) * h;
    double x = left ? margin : right ? w - margin - boxW : (w - boxW) / 2;
    double y = top ? margin : bottom ? h - margin - boxH : (h - boxH) / 2;
    x = std::round(x + ctx.get(offsetX_) * h);
    y = std::round(y + ctx.get(offsetY_) * h);

    const text::Overlay overlay = text::beginOverlay(ctx, in);
    const text::RgbaPlanes& planes = overlay.planes;
    const std::shared_ptr<WritableBuffer>& out = overlay.buffer;
    const int mw = std::max(1, int(boxW)), mh = std::max(1, int(boxH));
    if (ctx.get(box_)) {
        text::Mask background(mw, mh);
        background.rectangle(0, 0, boxW, boxH, 0.3 * font.sizePx);
        text::paint(background, int(x), int(y), ctx.get(boxColor_), planes);
    }
    text::Mask ink(mw, mh);
    ink.text(pad, pad, content, font, textAlign, markup);
    text::paint(ink, int(x), int(y), ctx.get(color_), planes);
    ctx.progress(1.0);
    ctx.set(result_, out);
}

}  // namespace darkroom
