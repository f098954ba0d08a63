#pragma once
#include <darkroom/filter.h>

namespace darkroom {

// Resamples an image to another size: colour and scalars filtered (box,
// bilinear or nearest), depth and ids never blended across edges.
class Resize final : public Filter {
public:
    PortList ports() const override;
    void execute(Context& ctx) override;
};

}  // namespace darkroom
