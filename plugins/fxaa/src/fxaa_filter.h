#pragma once
#include <darkroom/filter.h>

namespace darkroom {

// FXAA 3.11 quality (Lottes 2011) on linear colour: finds aliased edges from
// perceptual luma and blends each edge pixel with one neighbour across the
// edge. Channels other than R, G, B, A pass through unchanged.
class Fxaa final : public Filter {
public:
    PortList ports() const override;
    void execute(Context& ctx) override;
};

}  // namespace darkroom
