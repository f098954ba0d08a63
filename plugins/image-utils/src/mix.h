#pragma once
#include <darkroom/filter.h>

namespace darkroom {

// Combines a colour image with a factor channel or a second colour image:
// multiply (e.g. ambient occlusion applied to colour), blend, over, add.
class Mix final : public Filter {
public:
    enum class Mode { Multiply, Blend, Over, Add };

    PortList ports() const override { return {image_, other_, mode_, factorChannel_, amount_, result_}; }
    void execute(Context& ctx) override;

private:
    ImageIn image_{"image", "Base colour: linear R, G, B and optionally straight alpha A; every channel passes through",
                   {"R", "G", "B"}};
    OptionalImageIn other_{"other",
                           "multiply: the image holding factorChannel (unconnected: taken from 'image'); blend, over, "
                           "add: the second colour R, G, B (and A); same size as 'image'"};
    EnumIn<Mode> mode_{"mode",
                       {{Mode::Multiply, "multiply"}, {Mode::Blend, "blend"}, {Mode::Over, "over"}, {Mode::Add, "add"}},
                       Mode::Multiply,
                       "multiply: RGB *= mix(1, factor, amount); blend: mix(image, other, amount) on R, G, B, A; over: "
                       "'other' composited over 'image' with other's alpha times amount; add: RGB += amount * other"};
    StringIn factorChannel_{"factorChannel", "AO", "multiply: the float channel holding the factor, e.g. AO (SSAO) or SSDD"};
    FloatIn amount_{"amount", 1.0, 0.0, 1.0, "Strength: 0 leaves 'image' unchanged, 1 applies fully"};
    ImageOut result_{"image", "'image' with new R, G, B (and A for blend and over); all other channels passed through"};
};

}  // namespace darkroom
