#pragma once
#include "resample_taps.h"

#include <darkroom/filter.h>

#include <cstdint>

namespace darkroom {

// Resamples an image to another size: colour and scalars filtered (box,
// bilinear or nearest), depth and ids never blended across edges.
class Resize final : public Filter {
public:
    static constexpr std::int64_t kMaxSide = 65536;
    // 2^28 pixels: 1 GiB per float channel, already more than any preview or
    // supersampled reference needs; beyond it a typo would exhaust memory.
    static constexpr std::int64_t kMaxPixels = std::int64_t(1) << 28;

    PortList ports() const override { return {image_, width_, height_, scale_, filter_, result_}; }
    void execute(Context& ctx) override;

private:
    using F = utils::ResampleFilter;
    ImageIn image_{"image", "Any image; depth is read from Z when present"};
    IntIn width_{"width", 0, 0, kMaxSide, "Output width in pixels; 0 = from height keeping the aspect, or from scale"};
    IntIn height_{"height", 0, 0, kMaxSide, "Output height in pixels; 0 = from width keeping the aspect, or from scale"};
    FloatIn scale_{"scale", 1.0, 0.001, 64.0, "Size factor used when width and height are both 0"};
    EnumIn<F> filter_{"filter",
                      {{F::Box, "box"}, {F::Bilinear, "bilinear"}, {F::Nearest, "nearest"}},
                      F::Box,
                      "box: area average of the footprint (exact block means for integer factors, the choice for "
                      "supersampled references); bilinear: the two nearest pixels per axis; nearest: the pixel "
                      "containing the output centre"};
    ImageOut result_{"image",
                     "Resampled image, camera resolution updated. Float channels are filtered (R, G, B weighted by "
                     "alpha; NaN samples skipped); Z and uint32 channels come from one source pixel: the nearest "
                     "depth in the footprint (box) or the nearest pixel (bilinear, nearest)"};
};

}  // namespace darkroom
