#pragma once
#include <darkroom/filter.h>

namespace darkroom {

// Combines a colour image with a factor channel or a second colour image:
// multiply (e.g. ambient occlusion applied to colour), blend, over, add.
class Mix final : public Filter {
public:
    PortList ports() const override;
    void execute(Context& ctx) override;
};

}  // namespace darkroom
