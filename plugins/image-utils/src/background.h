#pragma once
#include <darkroom/filter.h>

namespace darkroom {

// Puts a colour or a vertical gradient behind the scene: the image composited
// over it with its straight alpha (or, without A, its depth as coverage).
class Background final : public Filter {
public:
    enum class Mode { Color, Gradient };

    PortList ports() const override { return {image_, mode_, color_, top_, bottom_, result_}; }
    void execute(Context& ctx) override;

private:
    ImageIn image_{"image",
                   "Linear R, G, B with straight alpha A; without A, finite depth Z counts as opaque and +inf as "
                   "empty",
                   {"R", "G", "B"}};
    EnumIn<Mode> mode_{"mode",
                       {{Mode::Color, "color"}, {Mode::Gradient, "gradient"}},
                       Mode::Gradient,
                       "color: one colour; gradient: 'top' at the first row to 'bottom' at the last, linear in between"};
    ColorIn color_{"color", Color{0.32f, 0.34f, 0.43f, 1.0f}, "Background colour (mode color)"};
    ColorIn top_{"top", Color{0.0f, 0.0f, 0.16f, 1.0f}, "Colour of the top row (mode gradient)"};
    ColorIn bottom_{"bottom", Color{0.32f, 0.34f, 0.43f, 1.0f}, "Colour of the bottom row (mode gradient)"};
    ImageOut result_{"image",
                     "The image over the background: R, G, B and A (1 where the background is opaque); other "
                     "channels, Z included, pass through",
                     {"R", "G", "B", "A"}};
};

}  // namespace darkroom
