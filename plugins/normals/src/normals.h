#pragma once
#include <darkroom/depth_input.h>
#include <darkroom/filter.h>
#include <darkroom/view_geometry.h>

namespace darkroom {

// World- and view-space normals and world positions reconstructed from depth
// Z and the camera carried by the image.
class Normals final : public Filter {
public:
    PortList ports() const override { return {image_, method_, replace_, camera_.port(), result_}; }
    void execute(Context& ctx) override;
    void beginSequence(const SequenceInfo&) override { camera_.beginSequence(); }

private:
    ImageIn image_{"image", "Depth Z (planar view depth, +inf background) with its camera in the metadata", {"Z"}};
    EnumIn<NormalMethod> method_{
        "method",
        {{NormalMethod::Central, "central"}, {NormalMethod::Nearest, "nearest"}, {NormalMethod::Extrapolated, "extrapolated"}},
        NormalMethod::Extrapolated,
        "central: central differences (wrong at depth edges); nearest: per axis the one-sided "
        "difference towards the closer depth; extrapolated: per axis the side whose two "
        "neighbours extrapolate best to the centre, central where both agree (most accurate)"};
    BoolIn replace_{"replace", false,
                    "When the input already has N.x/N.y/N.z (e.g. captured normals), overwrite them with "
                    "the reconstruction; when false they are kept and Nv is derived from them"};
    CameraSource camera_;  // the image's camera, or the image-space one (depth_input.h)
    ImageOut result_{"image",
                     "All input channels plus world normals N.x/N.y/N.z, view-space normals Nv.x/Nv.y/Nv.z "
                     "(x right, y up, z towards the viewer) and world positions P.x/P.y/P.z; NaN on "
                     "background",
                     {"N.x", "N.y", "N.z", "Nv.x", "Nv.y", "Nv.z", "P.x", "P.y", "P.z"}};
};

}  // namespace darkroom
