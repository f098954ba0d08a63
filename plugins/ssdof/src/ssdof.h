#pragma once
#include <darkroom/filter.h>

namespace darkroom {

// SSDoF: screen-space depth of field from colour and planar depth (see README).
class SSDoF final : public Filter {
public:
    PortList ports() const override;
    void execute(Context& ctx) override;
};

}  // namespace darkroom
