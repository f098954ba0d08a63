#include "color_legend.h"

#include "label_format.h"
#include <darkroom/text/text_limits.h>

#include <darkroom/colormap.h>
#include <darkroom/error.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace darkroom {

namespace {

// As ColorMapping's table: exact at both ends, linear in between.
constexpr int kTableSize = 4096;

Color tableColor(const std::vector<Color>& table, double t) {
    const double f = std::clamp(t, 0.0, 1.0) * (kTableSize - 1);
    const int k = std::min(int(f), kTableSize - 2);
    const float u = float(f - k), s = 1.0f - u;
    const Color& a = table[std::size_t(k)];
    const Color& b = table[std::size_t(k) + 1];
    return {s * a.r + u * b.r, s * a.g + u * b.g, s * a.b + u * b.b, 1.0f};
}

}  // namespace

void ColorLegend::execute(Context& ctx) {
    const BufferPtr in = ctx.get(image_);
    const int w = in->width(), h = in->height();
    const double minimum = ctx.get(minimum_), maximum = ctx.get(maximum_);
    const bool logScale = ctx.get(scale_) == Scale::Log;

    const bool finiteRange = std::isfinite(minimum) && std::isfinite(maximum);
    if (!finiteRange)
        ctx.warn("the range is not finite (" + fmt::format("{} to {}", minimum, maximum) +
                 "; the ColorMapping found no data?): the bar is drawn without tick labels");
    auto ticksFor = [&](int count) {
        std::vector<legend::Tick> t;
        if (!finiteRange) return t;
        t = logScale ? legend::logTicks(minimum, maximum, count) : legend::linearTicks(minimum, maximum, count);
        if (!ctx.get(labelFormat_).empty()) legend::applyLabelFormat(t, ctx.get(labelFormat_));
        return t;
    };

    legend::LegendStyle style;
    style.orientation = ctx.get(orientation_);
    style.anchor = ctx.get(anchor_);
    style.x = ctx.get(x_);
    style.y = ctx.get(y_);
    style.margin = ctx.get(margin_) * h;
    const bool horizontal = style.orientation == legend::Orientation::Horizontal;
    style.length = ctx.get(length_) * (horizontal ? w : h);
    style.thickness = ctx.get(thickness_) * h;
    style.font.family = ctx.get(font_);
    style.font.sizePx = ctx.get(fontSize_) * h;
    style.title = ctx.get(title_);
    const std::string& units = ctx.get(units_);
    if (!units.empty()) style.title += (style.title.empty() ? "(" : " (") + units + ")";
    text::checkTextLength(style.title, "the title with its units");
    // Fewer, evenly spaced labels rather than a gap where one would collide:
    // ask for fewer ticks until every label fits.
    std::vector<legend::Tick> ticks = ticksFor(int(ctx.get(ticks_)));
    legend::LegendLayout L = legend::layoutLegend(ticks, style, w, h);
    auto collides = [](const legend::LegendLayout& l) {
        return std::any_of(l.ticks.begin(), l.ticks.end(), [](const legend::PlacedTick& t) { return t.label.w <= 0; });
    };
    for (int count = int(ctx.get(ticks_)) - 1; count >= 2 && collides(L); --count) {
        std::vector<legend::Tick> fewer = ticksFor(count);
        if (fewer.size() >= ticks.size()) continue;
        ticks = std::move(fewer);
        L = legend::layoutLegend(ticks, style, w, h);
    }

    const ColorMapData map = loadColorMap(ctx.get(colormap_));
    const std::vector<Color> table = map.table(kTableSize);

    const text::Overlay overlay = text::beginOverlay(ctx, in);
    const text::RgbaPlanes& planes = overlay.planes;
    const std::shared_ptr<WritableBuffer>& out = overlay.buffer;

    // Everything but the bar is one colour over a coverage mask; the box its own.
    const int mx = int(L.box.x), my = int(L.box.y);
    const int mw = std::max(1, int(std::ceil(L.box.w))), mh = std::max(1, int(std::ceil(L.box.h)));
    if (ctx.get(box_)) {
        text::Mask box(mw, mh);
        box.rectangle(0, 0, L.box.w, L.box.h, 0.3 * style.font.sizePx);
        text::paint(box, mx, my, ctx.get(boxColor_), planes);
    }

    // The bar: the map itself, opaque, from the same table ColorMapping uses.
    const int bx0 = int(L.bar.x), by0 = int(L.bar.y), bw = int(L.bar.w), bh = int(L.bar.h);
    for (int y = std::max(0, by0); y < std::min(h, by0 + bh); ++y)
        for (int x = std::max(0, bx0); x < std::min(w, bx0 + bw); ++x) {
            const double t = horizontal ? (x + 0.5 - L.bar.x) / L.bar.w : (L.bar.bottom() - (y + 0.5)) / L.bar.h;
            const Color c = tableColor(table, t);
            const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
            planes.r[i] = c.r;
            planes.g[i] = c.g;
            planes.b[i] = c.b;
            if (planes.a) planes.a[i] = 1.0f;
        }

    text::Mask ink(mw, mh);
    const double lw = L.lineWidth;
    if (ctx.get(outline_))
        ink.frame(L.bar.x - mx - lw / 2, L.bar.y - my - lw / 2, L.bar.w + lw, L.bar.h + lw, lw);
    for (const auto& t : L.ticks) {
        if (horizontal)
            ink.line(t.position - mx, L.bar.bottom() - my, t.position - mx, L.bar.bottom() + L.tickLength - my, lw);
        else
            ink.line(L.bar.right() - mx, t.position - my, L.bar.right() + L.tickLength - mx, t.position - my, lw);
        if (t.label.w > 0) ink.text(t.label.x - mx, t.label.y - my, t.tick.label, style.font);
    }
    if (L.title.w > 0) {
        text::Font bold = style.font;
        bold.bold = true;
        ink.text(L.title.x - mx, L.title.y - my, style.title, bold);
    }
    text::paint(ink, mx, my, ctx.get(textColor_), planes);
    ctx.progress(1.0);
    ctx.set(result_, out);
}

}  // namespace darkroom
