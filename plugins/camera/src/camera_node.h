#pragma once
#include <darkroom/filter.h>

namespace darkroom {

// `Camera`: gives an image the camera that produced it, from the values a
// ParaView user knows, and optionally turns TTK's normalised depth back into
// planar distances. See plugins/camera/README.md.
class CameraNode : public Filter {
public:
    enum class Apply { Always, WhenMissing };
    enum class Depth { Distance, Normalised };

    PortList ports() const override {
        return {image_, apply_, position_, focalPoint_, viewUp_, parallelProjection_, viewAngle_, parallelScale_,
                depth_, near_, far_, result_};
    }
    void execute(Context& ctx) override;

private:
    ImageIn image_{"image", "Any image; Z is needed only to convert depth"};
    EnumIn<Apply> apply_{"apply",
                         {{Apply::Always, "always"}, {Apply::WhenMissing, "whenMissing"}},
                         Apply::Always,
                         "always: replace the image's camera; whenMissing: keep a camera the image already has"};
    Vec3In position_{"position", Vec3{0, 0, 1}, "Camera position in world units (ParaView: CameraPosition)"};
    Vec3In focalPoint_{"focalPoint", Vec3{0, 0, 0}, "Point the camera looks at (ParaView: CameraFocalPoint)"};
    Vec3In viewUp_{"viewUp", Vec3{0, 1, 0}, "Up direction of the view (ParaView: CameraViewUp)"};
    BoolIn parallelProjection_{"parallelProjection", false,
                               "Orthographic view (ParaView: CameraParallelProjection); otherwise perspective"};
    FloatIn viewAngle_{"viewAngle", 30.0, 1e-3, 179.999,
                       "Perspective: full vertical field of view in degrees (ParaView: CameraViewAngle)"};
    FloatIn parallelScale_{"parallelScale", 1.0, 1e-30, 1e30,
                           "Orthographic: half the view height in world units (ParaView: CameraParallelScale)"};
    EnumIn<Depth> depth_{"depth",
                         {{Depth::Distance, "distance"}, {Depth::Normalised, "normalised"}},
                         Depth::Distance,
                         "distance: Z already holds planar view depth, kept; normalised: Z holds depth normalised to "
                         "[0, 1] between near and far (TTK's CinemaImaging), turned into near + Z (far - near)"};
    FloatIn near_{"near", 0.0, 0.0, 1e30, "Near distance of the normalised depth (TTK: CamNearFar[0])"};
    FloatIn far_{"far", 1.0, 0.0, 1e30, "Far distance of the normalised depth (TTK: CamNearFar[1])"};
    ImageOut result_{"image", "The image with the camera set (every channel passes through; Z converted when asked)"};
};

}  // namespace darkroom
