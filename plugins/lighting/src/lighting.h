#pragma once
#include <darkroom/depth_input.h>
#include <darkroom/filter.h>

namespace darkroom {

// Lambert diffuse plus Blinn-Phong specular from captured or reconstructed
// normals: one to four directional lights or a headlight, an ambient term an
// optional AO multiplies.
class Lighting final : public Filter {
public:
    enum class Normals { Auto, Captured, Reconstructed };
    enum class Mode { Headlight, Directional };
    enum class Space { View, World };

    PortList ports() const override {
        return {image_,     geometry_,   ao_,         normals_,    mode_,       space_,      lightCount_,
                direction1_, intensity1_, direction2_, intensity2_, direction3_, intensity3_, direction4_,
                intensity4_, ambient_,    diffuse_,    specular_,   shininess_,  specularColor_, camera_.port(), result_};
    }
    void execute(Context& ctx) override;
    void beginSequence(const SequenceInfo&) override { camera_.beginSequence(); }

private:
    ImageIn image_{"image",
                   "Surface colour R, G, B (the albedo), depth Z and the camera; world-space normals N.x, N.y, N.z "
                   "when captured",
                   {"Z", "R", "G", "B"}};
    OptionalImageIn geometry_{"geometry",
                              "Optional G-buffer with the captured normals N.x, N.y, N.z, same size (e.g. the "
                              "CinemaReader's output: ColorMapping keeps only colour and Z)",
                              {"N.x", "N.y", "N.z"}};
    OptionalImageIn ao_{"ao",
                        "Optional ambient occlusion in channel AO (1 = open; SSAO's output, or rename with "
                        "ChannelSelect), same size: multiplies the ambient term only",
                        {"AO"}};
    EnumIn<Normals> normals_{"normals",
                             {{Normals::Auto, "auto"}, {Normals::Captured, "captured"},
                              {Normals::Reconstructed, "reconstructed"}},
                             Normals::Auto,
                             "captured: N.x/N.y/N.z (world space) of `geometry` when connected, else of `image`; "
                             "reconstructed: from depth (the Normals pass's extrapolated method); auto: captured "
                             "when present"};
    EnumIn<Mode> mode_{"mode",
                       {{Mode::Headlight, "headlight"}, {Mode::Directional, "directional"}},
                       Mode::Headlight,
                       "headlight: one light shining along the view direction (VTK's headlight; intensity1); "
                       "directional: lightCount lights from direction1..4"};
    EnumIn<Space> space_{"space",
                         {{Space::View, "view"}, {Space::World, "world"}},
                         Space::View,
                         "Frame of the light directions. view: x right, y up, z towards the viewer, so [0, 0, 1] "
                         "shines from the camera and [-1, 1, 1] from the upper left; world: the scene's axes (the "
                         "light stays put when the camera orbits)"};
    IntIn lightCount_{"lightCount", 1, 1, 4, "directional: how many of the four lights shine"};
    Vec3In direction1_{"direction1", Vec3{-0.4, 0.6, 1.0}, "Direction towards light 1 (need not be unit length)"};
    FloatIn intensity1_{"intensity1", 1.0, 0.0, 100.0, "Intensity of light 1 (also the headlight's)"};
    Vec3In direction2_{"direction2", Vec3{0.8, 0.1, 0.6}, "Direction towards light 2"};
    FloatIn intensity2_{"intensity2", 0.4, 0.0, 100.0, "Intensity of light 2"};
    Vec3In direction3_{"direction3", Vec3{0.0, -1.0, 0.3}, "Direction towards light 3"};
    FloatIn intensity3_{"intensity3", 0.25, 0.0, 100.0, "Intensity of light 3"};
    Vec3In direction4_{"direction4", Vec3{0.0, 0.3, -1.0}, "Direction towards light 4"};
    FloatIn intensity4_{"intensity4", 0.25, 0.0, 100.0, "Intensity of light 4"};
    FloatIn ambient_{"ambient", 0.2, 0.0, 10.0, "Ambient term (times AO when connected)"};
    FloatIn diffuse_{"diffuse", 0.8, 0.0, 10.0, "Lambert term: diffuse * intensity * max(0, N.L)"};
    FloatIn specular_{"specular", 0.2, 0.0, 10.0,
                      "Blinn-Phong term: specular * intensity * max(0, N.H)^shininess, where N.L > 0"};
    FloatIn shininess_{"shininess", 32.0, 1.0, 10000.0, "Blinn-Phong exponent (larger = smaller highlights)"};
    ColorIn specularColor_{"specularColor", Color{1.0f, 1.0f, 1.0f, 1.0f}, "Linear colour of the highlights"};
    CameraSource camera_;  // the image's camera, or the image-space one (depth_input.h)
    ImageOut result_{"image",
                     "R, G, B lit where Z is finite: albedo (ambient AO + diffuse sum I max(0, N.L)) + specular "
                     "colour sum I max(0, N.H)^shininess; background and other channels unchanged",
                     {"R", "G", "B"}};
};

}  // namespace darkroom
