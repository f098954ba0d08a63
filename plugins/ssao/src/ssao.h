#pragma once
#include <darkroom/filter.h>

namespace darkroom {

// SSAO: screen-space ambient occlusion from depth and the camera. Adds channel
// `AO` in [0, 1] (1 = unoccluded) and passes every input channel through.
class Ssao final : public Filter {
public:
    PortList ports() const override;
    void execute(Context& ctx) override;
};

}  // namespace darkroom
