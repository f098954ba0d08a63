#pragma once
#include <darkroom/filter.h>

namespace darkroom {

// `Camera`: gives an image the camera that produced it, from the values a
// ParaView user knows, and optionally turns TTK's normalised depth back into
// planar distances. See plugins/camera/README.md.
class CameraNode : public Filter {
public:
    PortList ports() const override;
    void execute(Context& ctx) override;
};

}  // namespace darkroom
