#pragma once
#include <darkroom/filter.h>

namespace darkroom {

// Source node: one image file -> a buffer (see framework/image_io.h for what
// each format becomes).
class ImageReader final : public Filter {
public:
    PortList ports() const override;
    void execute(Context& ctx) override;
};

}  // namespace darkroom
