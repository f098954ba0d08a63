#pragma once
#include <darkroom/filter.h>

#include <string>
#include <utility>
#include <vector>

namespace darkroom {

// FXAA 3.11 quality (Lottes 2011) on linear colour: finds aliased edges from
// perceptual luma and blends each edge pixel with one neighbour across the
// edge. Channels other than R, G, B, A pass through unchanged.
class Fxaa final : public Filter {
public:
    PortList ports() const override { return {image_, preset_, subpix_, edgeThreshold_, edgeThresholdMin_, result_}; }
    void execute(Context& ctx) override;

private:
    // The presets by their index in fxaa::presets().
    static std::vector<std::pair<int, std::string>> presetChoices();
    static int presetIndex(const std::string& name);

    ImageIn image_{"image", "Linear colour R, G, B (A optional: pixels with A <= 0 are background)", {"R", "G", "B"}};
    EnumIn<int> preset_{"preset", presetChoices(), presetIndex("12"),
                        "FXAA 3.11 quality preset: 10-15 medium dither (10 fastest), 20-29 less dither and "
                        "longer edge searches, 39 no dither (slowest); the last digit is the search length"};
    FloatIn subpix_{"subpix", 0.75, 0.0, 1.0,
                    "Sub-pixel aliasing removal: 0 off, 0.25 sharper, 0.75 FXAA's default, 1 softest"};
    FloatIn edgeThreshold_{"edgeThreshold", 0.166, 0.0, 1.0,
                           "Local luma contrast needed to process a pixel, relative to the brightest pixel of "
                           "its cross: 0.333 too little, 0.166 default, 0.125 high quality, 0.063 overkill"};
    FloatIn edgeThresholdMin_{"edgeThresholdMin", 0.0833, 0.0, 1.0,
                              "Absolute luma contrast below which dark pixels are skipped: 0.0833 default, "
                              "0.0625 high quality, 0.0312 visible limit"};
    ImageOut result_{"image",
                     "Anti-aliased R, G, B (and A, blended with the same weight); every other channel "
                     "passes through unchanged; NaN or transparent pixels are never mixed into others",
                     {"R", "G", "B"}};
};

}  // namespace darkroom
