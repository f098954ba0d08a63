#include "legend_layout.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace darkroom::legend {

namespace {

// Snaps a line centre so that a line of integer width `width` covers whole pixels.
double snapLine(double centre, double width) {
    const bool odd = int(std::lround(width)) % 2 == 1;
    return odd ? std::floor(centre) + 0.5 : std::round(centre);
}

// The box's top-left corner on the image for the style's anchor.
std::pair<double, double> boxCorner(const LegendStyle& s, int imageWidth, int imageHeight, double boxW, double boxH) {
    double bx = s.x, by = s.y;
    switch (s.anchor) {
        case Anchor::BottomRight: bx = imageWidth - s.margin - boxW; by = imageHeight - s.margin - boxH; break;
        case Anchor::BottomLeft: bx = s.margin; by = imageHeight - s.margin - boxH; break;
        case Anchor::TopRight: bx = imageWidth - s.margin - boxW; by = s.margin; break;
        case Anchor::TopLeft: bx = s.margin; by = s.margin; break;
        case Anchor::BottomCenter: bx = (imageWidth - boxW) / 2; by = imageHeight - s.margin - boxH; break;
        case Anchor::TopCenter: bx = (imageWidth - boxW) / 2; by = s.margin; break;
        case Anchor::Pixel: break;
    }
    return {bx, by};
}

// Ticks on the bar (lines snapped to whole pixels) and their labels, moved
// by (ox, oy); along the drawing direction, a label that would come closer
// than `spacing` to the previous one is dropped (width 0).
void placeTicks(const std::vector<Tick>& ticks, const std::vector<double>& positions, const std::vector<Rect>& labels,
                bool horizontal, double ox, double oy, double spacing, LegendLayout& L) {
    double lastEnd = -1e300;  // far edge of the last drawn label along the bar axis
    std::vector<std::size_t> order(ticks.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    // Along the drawing direction: left to right, or top to bottom.
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return positions[a] < positions[b]; });
    L.ticks.resize(ticks.size());
    for (std::size_t k : order) {
        PlacedTick& p = L.ticks[k];
        p.tick = ticks[k];
        const double exact = (horizontal ? L.bar.x : L.bar.y) + positions[k];
        p.position = snapLine(exact, L.lineWidth);
        Rect r{ox + labels[k].x, oy + labels[k].y, labels[k].w, labels[k].h};
        const double start = horizontal ? r.x : r.y, end = horizontal ? r.right() : r.bottom();
        if (start < lastEnd + spacing) {
            r.w = 0;  // would collide with the previous label
        } else {
            lastEnd = end;
        }
        p.label = r;
    }
}

}  // namespace

LegendLayout layoutLegend(const std::vector<Tick>& ticks, const LegendStyle& s, int imageWidth, int imageHeight) {
    LegendLayout L;
    const double font = s.font.sizePx;
    L.lineWidth = std::max(1.0, std::round(font / 14.0));
    L.tickLength = std::round(std::max(2.0, 0.3 * font));
    L.padding = std::round(0.5 * font);
    const double gap = std::round(0.2 * font);  // between tick and label, and below the title
    const bool horizontal = s.orientation == Orientation::Horizontal;

    const double length = std::max(2.0, std::round(s.length));
    const double thickness = std::max(1.0, std::round(s.thickness));
    text::Font titleFont = s.font;
    titleFont.bold = true;
    const text::TextBox titleBox = s.title.empty() ? text::TextBox{} : text::measure(s.title, titleFont);

    // Labels measured once; laid out relative to the bar at (0, 0).
    std::vector<text::TextBox> boxes;
    double widest = 0, tallest = 0;
    for (const Tick& t : ticks) {
        boxes.push_back(text::measure(t.label, s.font));
        widest = std::max(widest, boxes.back().width);
        tallest = std::max(tallest, boxes.back().height);
    }

    // Content relative to the bar's top-left corner at (0, 0).
    Rect bar{0, 0, horizontal ? length : thickness, horizontal ? thickness : length};
    double left = 0, top = 0, right = bar.w, bottom = bar.h;
    std::vector<Rect> labels(ticks.size());
    std::vector<double> positions(ticks.size());
    for (std::size_t i = 0; i < ticks.size(); ++i) {
        const double t = std::clamp(ticks[i].t, 0.0, 1.0);
        if (horizontal) {
            positions[i] = t * bar.w;
            labels[i] = {positions[i] - boxes[i].width / 2, bar.h + L.tickLength + gap, boxes[i].width, boxes[i].height};
        } else {
            positions[i] = bar.h - t * bar.h;
            labels[i] = {bar.w + L.tickLength + gap, positions[i] - boxes[i].height / 2, boxes[i].width, boxes[i].height};
        }
        left = std::min(left, labels[i].x);
        right = std::max(right, labels[i].right());
        top = std::min(top, labels[i].y);
        bottom = std::max(bottom, labels[i].bottom());
    }
    if (ticks.empty()) {
        if (horizontal) bottom = bar.h + L.tickLength;
        else right = bar.w + L.tickLength;
    }
    Rect title;
    if (!s.title.empty()) {
        // Above everything else: centred on a horizontal bar, left-aligned
        // with a vertical one.
        title = {horizontal ? (bar.w - titleBox.width) / 2 : 0, top - gap - titleBox.height, titleBox.width,
                 titleBox.height};
        left = std::min(left, title.x);
        right = std::max(right, title.right());
        top = title.y;
    }
    const double boxW = std::ceil(right - left + 2 * L.padding);
    const double boxH = std::ceil(bottom - top + 2 * L.padding);

    // The box on the image.
    auto [bx, by] = boxCorner(s, imageWidth, imageHeight, boxW, boxH);
    bx = std::round(bx);
    by = std::round(by);
    L.box = {bx, by, boxW, boxH};
    // Shift: content origin so that (left, top) lands at the box corner plus padding.
    const double ox = bx + L.padding - std::floor(left), oy = by + L.padding - std::floor(top);
    L.bar = {ox + bar.x, oy + bar.y, bar.w, bar.h};
    if (!s.title.empty()) L.title = {ox + title.x, oy + title.y, title.w, title.h};

    placeTicks(ticks, positions, labels, horizontal, ox, oy, 0.5 * font, L);
    return L;
}

}  // namespace darkroom::legend
