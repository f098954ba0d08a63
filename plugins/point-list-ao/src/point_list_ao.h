#pragma once
#include <darkroom/filter.h>

namespace darkroom {

// PointListAO: ambient occlusion cast by the spheres and round lines of a
// point list (the list a capture stored beside each entry), in closed form
// per primitive, onto every pixel of a G-buffer. Made for particles and
// streamlines, which a depth buffer cannot represent (docs/accuracy.md).
class PointListAo final : public Filter {
public:
    enum class RadiusUnits { World, ImageHeight };
    enum class ExistingAo { Multiply, Replace };

    PortList ports() const override {
        return {image_, points_, row_, radius_, radiusUnits_, pointRadius_, radiusScale_, existing_,
                intensity_, power_, result_};
    }
    void execute(Context& ctx) override;

private:
    ImageIn image_{"image",
                   "G-buffer of the receivers: planar depth Z and the camera in its metadata (required: the list "
                   "is in world units); world-space normals N.x/N.y/N.z are used when present",
                   {"Z"}};
    PathIn points_{"points", "",
                   "The occluders: a point list CSV (x, y, z, optional radius and fields; consecutive rows with "
                   "one value in a `line` column form a round line) or the vertices of a mesh file. {column} "
                   "placeholders are filled from `row`, e.g. {FILE_particles}"};
    RowIn row_{"row", "The Cinema row for placeholders in `points` (connect CinemaReader's row)"};
    FloatIn radius_{"radius", 0.05, 1e-6, 1e9, "Occlusion radius (rays longer than this are not occluded), in radiusUnits"};
    EnumIn<RadiusUnits> radiusUnits_{"radiusUnits",
                                     {{RadiusUnits::World, "world"}, {RadiusUnits::ImageHeight, "imageHeight"}},
                                     RadiusUnits::ImageHeight,
                                     "world: world units; imageHeight: a fraction of the image height at each "
                                     "pixel's depth (as SSAO)"};
    FloatIn pointRadius_{"pointRadius", 0.02, 0.0, 1e9, "Radius in world units of points the list gives none"};
    FloatIn radiusScale_{"radiusScale", 1.0, 0.0, 1e9,
                         "Multiplies every point's radius (set it as for Spheres, so the occluders are the spheres "
                         "drawn)"};
    EnumIn<ExistingAo> existing_{"existingAO",
                                 {{ExistingAo::Multiply, "multiply"}, {ExistingAo::Replace, "replace"}},
                                 ExistingAo::Multiply,
                                 "An AO channel already in the input (e.g. SSAO of the captured surfaces): multiply "
                                 "it by the list's occlusion, or replace it"};
    FloatIn intensity_{"intensity", 1.0, 0.0, 10.0, "Scales occlusion: AO = 1 - intensity (1 - AO), then clamped"};
    FloatIn power_{"power", 1.0, 0.1, 10.0, "Exponent applied to AO after intensity"};
    ImageOut result_{"image", "The input channels plus AO in [0, 1] (1 = unoccluded; background keeps 1)", {"AO"}};
};

}  // namespace darkroom
