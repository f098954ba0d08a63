#pragma once
#include "legend_layout.h"

#include <darkroom/filter.h>

namespace darkroom {

// A colour bar with tick labels at round numbers, a title and units, drawn
// over the image from the same map, range and scale a ColorMapping used.
class ColorLegend final : public Filter {
public:
    enum class Scale { Linear, Log };

    PortList ports() const override {
        return {image_,  colormap_, minimum_,   maximum_,   scale_,    orientation_, anchor_,    x_,
                y_,      margin_,   length_,    thickness_, fontSize_, font_,        title_,     units_,
                ticks_,  labelFormat_, textColor_, box_,    boxColor_, outline_,     result_};
    }
    void execute(Context& ctx) override;

private:
    static constexpr double kBig = 1e30;
    ImageIn image_{"image", "Linear colour R, G, B (and A) to draw on", {"R", "G", "B"}};
    ColorMapIn colormap_{"colormap", "viridis",
                         "The map of the bar; connect ColorMapping's usedColormap so it is the same"};
    FloatIn minimum_{"minimum", 0.0, -kBig, kBig,
                     "Value at the start of the map; connect ColorMapping's usedMinimum"};
    FloatIn maximum_{"maximum", 1.0, -kBig, kBig, "Value at the end of the map; connect ColorMapping's usedMaximum"};
    EnumIn<Scale> scale_{"scale",
                         {{Scale::Linear, "linear"}, {Scale::Log, "log"}},
                         Scale::Linear,
                         "linear, or log (ticks at decades); connect ColorMapping's usedScale"};
    EnumIn<legend::Orientation> orientation_{
        "orientation",
        {{legend::Orientation::Horizontal, "horizontal"}, {legend::Orientation::Vertical, "vertical"}},
        legend::Orientation::Horizontal,
        "horizontal: minimum on the left; vertical: minimum at the bottom"};
    EnumIn<legend::Anchor> anchor_{"anchor",
                                   {{legend::Anchor::BottomRight, "bottomRight"},
                                    {legend::Anchor::BottomLeft, "bottomLeft"},
                                    {legend::Anchor::TopRight, "topRight"},
                                    {legend::Anchor::TopLeft, "topLeft"},
                                    {legend::Anchor::BottomCenter, "bottomCenter"},
                                    {legend::Anchor::TopCenter, "topCenter"},
                                    {legend::Anchor::Pixel, "pixel"}},
                                   legend::Anchor::BottomRight,
                                   "Where the legend sits: a corner or edge centre (at `margin` from the edges), "
                                   "or `pixel` (its top-left corner at x, y)"};
    FloatIn x_{"x", 0.0, -1e6, 1e6, "anchor pixel: left edge of the legend's box, in pixels"};
    FloatIn y_{"y", 0.0, -1e6, 1e6, "anchor pixel: top edge of the legend's box, in pixels"};
    FloatIn margin_{"margin", 0.03, 0.0, 1.0, "Gap between the box and the image edges, as a fraction of the image height"};
    FloatIn length_{"length", 0.4, 0.01, 1.0,
                    "Length of the bar as a fraction of the image width (horizontal) or height (vertical)"};
    FloatIn thickness_{"thickness", 0.03, 0.001, 0.5, "Thickness of the bar as a fraction of the image height"};
    FloatIn fontSize_{"fontSize", 0.028, 0.002, 0.5, "Label size (em) as a fraction of the image height"};
    StringIn font_{"font", "DejaVu Sans", "Font family (fontconfig name); DejaVu Sans ships with Debian's fonts-dejavu-core"};
    StringIn title_{"title", "", "Title above the bar (e.g. the field's name)"};
    StringIn units_{"units", "", "Units, shown after the title in parentheses"};
    IntIn ticks_{"ticks", 5, 2, 20, "About how many tick labels (round numbers inside the range)"};
    StringIn labelFormat_{"labelFormat", "",
                          "Format of the tick labels, e.g. .2f or .1e (fmt / Python syntax); empty = as many "
                          "decimals as the tick step needs"};
    ColorIn textColor_{"textColor", Color{0.0f, 0.0f, 0.0f, 1.0f}, "Linear colour of text, ticks and outline"};
    BoolIn box_{"box", true, "Draw a background box behind the legend"};
    ColorIn boxColor_{"boxColor", Color{1.0f, 1.0f, 1.0f, 0.85f}, "Linear colour and opacity of the background box"};
    BoolIn outline_{"outline", true, "Draw a thin frame around the bar"};
    ImageOut result_{"image", "The input with the legend drawn over R, G, B (and A); other channels pass through",
                     {"R", "G", "B"}};
};

}  // namespace darkroom
