#pragma once
#include <darkroom/filter.h>

namespace darkroom {

// Keeps (optionally renaming) or drops named channels of an image.
class ChannelSelect final : public Filter {
public:
    PortList ports() const override;
    void execute(Context& ctx) override;
};

}  // namespace darkroom
