#pragma once
#include <darkroom/depth_input.h>
#include <darkroom/filter.h>

namespace darkroom {

// Image-based silhouettes (the Cinema Darkroom paper's IBS pass): outlines at
// depth and object-id discontinuities, optionally with a headlight lighting term.
class Ibs final : public Filter {
public:
    enum class Side { Near, Far };

    PortList ports() const override {
        return {image_, width_, strength_, color_, depthThreshold_, side_, objectIds_, lighting_, luminance_,
                ambient_, camera_.port(), result_};
    }
    void execute(Context& ctx) override;
    void beginSequence(const SequenceInfo&) override { camera_.beginSequence(); }

private:
    ImageIn image_{"image",
                   "Depth Z (+inf background); optional objectId (uint32), R, G, B, A, N.x/N.y/N.z and "
                   "the camera (needed for lighting)",
                   {"Z"}};
    FloatIn width_{"width", 1.0, 0.0, 32.0,
                   "Outline width in pixels: pixels within this distance of a discontinuity (1 = only "
                   "the 4-neighbours of the jump)"};
    FloatIn strength_{"strength", 1.0, 0.0, 1.0, "Opacity of the outline colour over the image"};
    ColorIn color_{"color", Color{0.0f, 0.0f, 0.0f, 1.0f}, "Linear colour of the outlines (its alpha scales strength)"};
    FloatIn depthThreshold_{"depthThreshold", 0.05, 0.0, 1e6,
                            "Relative depth jump |Z1 - Z2| / nearer Z above which neighbours are separate surfaces"};
    EnumIn<Side> side_{"side",
                       {{Side::Near, "near"}, {Side::Far, "far"}},
                       Side::Near,
                       "near: outline the nearer surface of each jump (background untouched, objects keep "
                       "their footprint); far: the surface or background behind it (a halo; alpha raised)"};
    BoolIn objectIds_{"objectIds", true, "Also draw outlines where the uint32 channel objectId changes"};
    BoolIn lighting_{"lighting", false,
                     "Multiply R, G, B by luminance * (ambient + (1 - ambient) max(0, N.V)), a headlight "
                     "(N from N.* or reconstructed from depth)"};
    FloatIn luminance_{"luminance", 1.0, 0.0, 100.0, "Light intensity of the lighting term"};
    FloatIn ambient_{"ambient", 0.2, 0.0, 1.0, "Share of the light that does not depend on the normal"};
    CameraSource camera_;  // the image's camera, or the image-space one (depth_input.h)
    ImageOut result_{"image",
                     "All input channels plus Silhouette in [0, 1]; R, G, B (and A) with the outlines "
                     "(and lighting) applied when the input has colour",
                     {"Silhouette"}};
};

}  // namespace darkroom
