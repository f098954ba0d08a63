#pragma once
#include <darkroom/depth_input.h>
#include <darkroom/filter.h>

namespace darkroom {

// Ssdof: screen-space depth of field from colour and planar depth (see README).
class Ssdof final : public Filter {
public:
    enum class Method { Disc, Hexagon };

    PortList ports() const override {
        return {image_, focalDistance_, aperture_, maxBlur_, method_, samples_, rotation_, camera_.port(), result_};
    }
    void execute(Context& ctx) override;
    void beginSequence(const SequenceInfo&) override { camera_.beginSequence(); }

private:
    static constexpr double kBig = 1e30;

    ImageIn image_{"image",
                   "Linear R, G, B (A optional, straight alpha) and planar depth Z (+inf = background); "
                   "the camera in the metadata gives the field of view",
                   {"R", "G", "B", "Z"}};
    FloatIn focalDistance_{"focalDistance", 0.0, 0.0, kBig,
                           "Planar depth in focus, world units; 0 = auto-focus on the median depth of the 5x5 "
                           "centre pixels (infinity when they are all background)"};
    FloatIn aperture_{"aperture", 0.05, 0.0, kBig,
                      "Lens diameter in world units (a real lens: focal length / f-number); 0 = pinhole, "
                      "everything sharp"};
    FloatIn maxBlur_{"maxBlur", 16.0, 0.0, 128.0, "Largest circle-of-confusion radius, pixels"};
    EnumIn<Method> method_{"method",
                           {{Method::Disc, "disc"}, {Method::Hexagon, "hexagon"}},
                           Method::Disc,
                           "disc: round aperture, golden-angle spiral gather with `samples` taps; hexagon: "
                           "hexagonal aperture as separable skewed box blurs (McIntosh et al. 2012), taps follow "
                           "the CoC"};
    IntIn samples_{"samples", 32, 4, 1024, "Taps of the disc gather per layer (disc method)"};
    FloatIn rotation_{"rotation", 0.0, 0.0, 60.0,
                      "Hexagon orientation: a corner points this many degrees clockwise from up (hexagon "
                      "method)"};
    CameraSource camera_;  // the image's camera, or the image-space one (depth_input.h)
    ImageOut result_{"image",
                     "Input channels passed through with R, G, B (and A if present) blurred; in-focus "
                     "pixels without near-field bleeding are bit-identical",
                     {"R", "G", "B"}};
};

}  // namespace darkroom
