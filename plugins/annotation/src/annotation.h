#pragma once
#include <darkroom/filter.h>

#include <string>

namespace darkroom {

// A block of text over the image, with placeholders filled from the Cinema
// row being shaded ("t = {time:.2f} s").
class Annotation final : public Filter {
public:
    enum class Anchor { TopLeft, Top, TopRight, Left, Center, Right, BottomLeft, Bottom, BottomRight };
    enum class Align { Auto, Left, Center, Right };

    PortList ports() const override {
        return {image_, text_, row_, anchor_, margin_, offsetX_, offsetY_, fontSize_, font_, bold_,
                markup_, align_, color_, box_, boxColor_, padding_, result_};
    }
    void execute(Context& ctx) override;

private:
    ImageIn image_{"image", "Linear colour R, G, B (and A) to draw on", {"R", "G", "B"}};
    StringIn text_{"text", "",
                   "The text. {column} is replaced by that column of `row` as written, {column:.2f} formats it as a "
                   "number (Python/fmt syntax), {{ and }} are braces; a line break, or the two characters \\n, "
                   "starts a new line"};
    RowIn row_{"row",
                  "The Cinema row the placeholders come from: connect CinemaReader's row (or type "
                  "'time=0.5, phi=30')"};
    EnumIn<Anchor> anchor_{"anchor",
                           {{Anchor::TopLeft, "topLeft"},
                            {Anchor::Top, "top"},
                            {Anchor::TopRight, "topRight"},
                            {Anchor::Left, "left"},
                            {Anchor::Center, "center"},
                            {Anchor::Right, "right"},
                            {Anchor::BottomLeft, "bottomLeft"},
                            {Anchor::Bottom, "bottom"},
                            {Anchor::BottomRight, "bottomRight"}},
                           Anchor::TopLeft,
                           "Which point of the image the same point of the text's box is placed at"};
    FloatIn margin_{"margin", 0.02, 0.0, 1.0,
                    "Gap between the box and the image edges it is anchored to, as a fraction of the image height"};
    FloatIn offsetX_{"offsetX", 0.0, -10.0, 10.0, "Further shift to the right, as a fraction of the image height"};
    FloatIn offsetY_{"offsetY", 0.0, -10.0, 10.0, "Further shift downwards, as a fraction of the image height"};
    FloatIn fontSize_{"fontSize", 0.04, 0.002, 1.0, "Em size as a fraction of the image height"};
    StringIn font_{"font", "DejaVu Sans", "Font family (fontconfig name); DejaVu Sans ships with Debian's fonts-dejavu-core"};
    BoolIn bold_{"bold", false, "Bold text"};
    BoolIn markup_{"markup", false, "Read the text as Pango markup (<b>, <i>, <sup>2</sup>, &amp; for &)"};
    EnumIn<Align> align_{"align",
                         {{Align::Auto, "auto"}, {Align::Left, "left"}, {Align::Center, "center"}, {Align::Right, "right"}},
                         Align::Auto,
                         "How lines are aligned within the block; auto follows the anchor (left, centre or right)"};
    ColorIn color_{"color", Color{0.0f, 0.0f, 0.0f, 1.0f}, "Linear colour (and opacity) of the text"};
    BoolIn box_{"box", false, "Draw a background box behind the text"};
    ColorIn boxColor_{"boxColor", Color{1.0f, 1.0f, 1.0f, 0.85f}, "Linear colour and opacity of the box"};
    FloatIn padding_{"padding", 0.4, 0.0, 10.0, "Space between the text and the box's edge, in em"};
    ImageOut result_{"image", "The input with the text drawn over R, G, B (and A); other channels pass through",
                     {"R", "G", "B"}};
};

}  // namespace darkroom
