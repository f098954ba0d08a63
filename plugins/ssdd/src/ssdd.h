#pragma once
#include <darkroom/depth_input.h>
#include <darkroom/filter.h>

namespace darkroom {

// Screen-space depth darkening (Luft, Colditz, Deussen 2006, "Image enhancement
// by unsharp masking the depth buffer"): dD = G_sigma * D - D, darkening where
// a pixel lies behind its blurred surroundings.
class Ssdd final : public Filter {
public:
    enum class SigmaUnits { ImageHeight, Pixels };

    PortList ports() const override { return {image_, strength_, sigma_, sigmaUnits_, apply_, camera_.port(), result_}; }
    void execute(Context& ctx) override;
    void beginSequence(const SequenceInfo&) override { camera_.beginSequence(); }

private:
    ImageIn image_{"image", "Depth Z (planar view depth, +inf background) with its camera in the metadata", {"Z"}};
    FloatIn strength_{"strength", 0.5, 0.0, 100.0,
                      "Darkening per unit of depth difference, measured in the world size of sigma at the "
                      "pixel's depth: factor = exp(-strength * max(0, -dD) / sigmaWorld)"};
    FloatIn sigma_{"sigma", 0.01, 0.0, 512.0,
                   "Standard deviation of the Gaussian, in pixels or as a fraction of the image height"};
    EnumIn<SigmaUnits> sigmaUnits_{"sigmaUnits",
                                   {{SigmaUnits::ImageHeight, "imageHeight"}, {SigmaUnits::Pixels, "pixels"}},
                                   SigmaUnits::ImageHeight,
                                   "imageHeight: sigma is a fraction of the image height (same look at any "
                                   "resolution); pixels: sigma in pixels"};
    BoolIn apply_{"apply", false, "Also multiply R, G, B (when present) by the factor; otherwise only add SSDD"};
    CameraSource camera_;  // the image's camera, or the image-space one (depth_input.h)
    ImageOut result_{"image",
                     "All input channels plus SSDD, a darkening factor in [0, 1] (1 = unchanged; 1 on "
                     "background and where Z is not finite)",
                     {"SSDD"}};
};

}  // namespace darkroom
