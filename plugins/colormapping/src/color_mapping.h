#pragma once
#include <darkroom/filter.h>

namespace darkroom {

// Scalar channel -> linear RGBA through a colour map (the paper's
// ColorMapping pass). Depth Z passes through; background (Z = +inf) becomes
// transparent.
class ColorMapping final : public Filter {
public:
    PortList ports() const override;
    void execute(Context& ctx) override;
};

}  // namespace darkroom
