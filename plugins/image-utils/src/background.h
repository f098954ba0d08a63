#pragma once
#include <darkroom/filter.h>

namespace darkroom {

// Puts a colour or a vertical gradient behind the scene: the image composited
// over it with its straight alpha (or, without A, its depth as coverage).
class Background final : public Filter {
public:
    PortList ports() const override;
    void execute(Context& ctx) override;
};

}  // namespace darkroom
