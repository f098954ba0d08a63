#pragma once
#include <darkroom/filter.h>

namespace darkroom {

// The paper's Compositing pass: per pixel, the input with the smallest finite
// depth wins and brings every channel with it (z-buffer merge of separately
// captured G-buffers).
class Compositing final : public Filter {
public:
    PortList ports() const override;
    void execute(Context& ctx) override;
};

}  // namespace darkroom
