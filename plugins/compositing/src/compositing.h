#pragma once
#include <darkroom/filter.h>

namespace darkroom {

// The paper's Compositing pass: per pixel, the input with the smallest finite
// depth wins and brings every channel with it (z-buffer merge of separately
// captured G-buffers).
class Compositing final : public Filter {
public:
    PortList ports() const override { return {images_, depthChannel_, result_}; }
    void execute(Context& ctx) override;

private:
    ImagesIn images_{"images",
                     "G-buffers to merge, any number, all the same size, each with a depth channel; edge order is "
                     "the tie-break order (lower wins)"};
    StringIn depthChannel_{"depthChannel", "Z", "Float channel holding planar depth (+inf or NaN = background)"};
    ImageOut result_{"image",
                     "Per pixel every channel of the nearest input; the union of the inputs' channels; the first "
                     "input's camera"};
};

}  // namespace darkroom
