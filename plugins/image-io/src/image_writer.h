#pragma once
#include <darkroom/filter.h>

namespace darkroom {

// Sink node: writes its input to a file, atomically. It has no outputs; the
// runner executes it because it is a sink.
class ImageWriter final : public Filter {
public:
    PortList ports() const override;
    void execute(Context& ctx) override;
};

}  // namespace darkroom
