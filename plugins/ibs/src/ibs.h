#pragma once
#include <darkroom/filter.h>

namespace darkroom {

// Image-based silhouettes (the Cinema Darkroom paper's IBS pass): outlines at
// depth and object-id discontinuities, optionally with a headlight lighting term.
class Ibs final : public Filter {
public:
    PortList ports() const override;
    void execute(Context& ctx) override;
};

}  // namespace darkroom
