#pragma once
#include <darkroom/filter.h>

namespace darkroom {

// Eye-dome lighting (Boucheny, Ribes, Bonneau, Guyon 2009), as VTK's
// vtkEDLShading / ParaView's "Eye Dome Lighting" and Potree: a pixel is
// shaded by the neighbours in front of it, in log depth, over several
// scales. Depth only: no normals, no camera.
class EyeDomeLighting final : public Filter {
public:
    PortList ports() const override { return {image_, strength_, radius_, scales_, apply_, result_}; }
    void execute(Context& ctx) override;

    // Potree's gain (response * 300 * strength), which gives strength 1 the
    // look ParaView and Potree users know.
    static constexpr double kGain = 300.0;

private:
    ImageIn image_{"image", "Planar depth Z (+inf background); R, G, B are shaded when present and `apply` is on", {"Z"}};
    FloatIn strength_{"strength", 1.0, 0.0, 100.0,
                      "Shading strength: EDL = exp(-300 strength response), response the mean log2 depth drop "
                      "to the 8 neighbours"};
    FloatIn radius_{"radius", 1.0, 0.5, 64.0, "Distance of the 8 neighbours at the finest scale, in pixels"};
    IntIn scales_{"scales", 2, 1, 6,
                  "How many scales: scale s samples at radius 2^s times `radius`, weighted 2^-s (2 scales: 2/3 "
                  "and 1/3, VTK's 0.7 / 0.3)"};
    BoolIn apply_{"apply", true, "Multiply R, G, B by EDL on surface pixels (when the image has colour)"};
    ImageOut result_{"image",
                     "All input channels plus EDL in (0, 1] (1 = unshaded; 1 on background); R, G, B shaded when "
                     "applied",
                     {"EDL"}};
};

}  // namespace darkroom
