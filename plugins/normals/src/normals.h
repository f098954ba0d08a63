#pragma once
#include <darkroom/filter.h>

namespace darkroom {

// World- and view-space normals and world positions reconstructed from depth
// Z and the camera carried by the image.
class Normals final : public Filter {
public:
    PortList ports() const override;
    void execute(Context& ctx) override;
};

}  // namespace darkroom
