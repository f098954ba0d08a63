#pragma once
#include <darkroom/filter.h>

namespace darkroom {

// Screen-space depth darkening (Luft, Colditz, Deussen 2006, "Image enhancement
// by unsharp masking the depth buffer"): dD = G_sigma * D - D, darkening where
// a pixel lies behind its blurred surroundings.
class Ssdd final : public Filter {
public:
    PortList ports() const override;
    void execute(Context& ctx) override;
};

}  // namespace darkroom
