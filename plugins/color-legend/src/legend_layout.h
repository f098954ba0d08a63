#pragma once
// The geometry of a colour legend on an image of a given size: the box, the
// bar, each tick's pixel position and label place, and the title. Pure
// arithmetic on the text metrics (text_drawing.h), so the tests can check
// positions without reading pixels.
#include "nice_ticks.h"
#include <darkroom/text/text_drawing.h>

#include <string>
#include <vector>

namespace darkroom::legend {

enum class Orientation { Horizontal, Vertical };
enum class Anchor { BottomRight, BottomLeft, TopRight, TopLeft, BottomCenter, TopCenter, Pixel };

struct Rect {
    double x = 0, y = 0, w = 0, h = 0;
    double right() const { return x + w; }
    double bottom() const { return y + h; }
};

// Every length in pixels of the target image.
struct LegendStyle {
    Orientation orientation = Orientation::Horizontal;
    Anchor anchor = Anchor::BottomRight;
    double x = 0, y = 0;   // Anchor::Pixel: top-left corner of the box
    double margin = 0;     // corner anchors: gap between box and image edges
    double length = 0;     // of the bar, along its axis
    double thickness = 0;  // of the bar, across it
    text::Font font;       // labels; the title uses the same font, bold
    std::string title;     // "Height (m)": title and units already joined
    bool box = true;       // whether a background box is drawn (its padding is laid out either way)
};

struct PlacedTick {
    Tick tick;
    double position = 0;  // pixel coordinate of the tick's centre line along the bar axis
    Rect label;           // where its label is drawn (empty w = not drawn: would overlap a neighbour)
};

struct LegendLayout {
    Rect box;  // background box (bar, ticks, labels and title plus padding)
    Rect bar;  // whole pixels
    double lineWidth = 1, tickLength = 0, padding = 0;
    std::vector<PlacedTick> ticks;
    Rect title;  // empty w = no title
};

// Places bar, ticks, labels and title. Horizontal bars run from `minimum` on
// the left to `maximum` on the right, vertical ones from the bottom up (as
// ParaView's scalar bar). Tick lines are `lineWidth` pixels wide and snapped
// so they cover whole pixels (an odd width centred on a pixel centre, an even
// one on a pixel edge): a tick is within half a pixel of the exact position
// bar.x + t * bar.w (bar.bottom() - t * bar.h vertically), and crisp. A label
// that would overlap the previous drawn one is not drawn.
LegendLayout layoutLegend(const std::vector<Tick>& ticks, const LegendStyle& style, int imageWidth, int imageHeight);

}  // namespace darkroom::legend
