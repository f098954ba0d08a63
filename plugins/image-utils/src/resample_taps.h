#pragma once
// One axis of a separable resampling: which source pixels each output pixel
// reads and with what weight.
#include <string>
#include <vector>

namespace darkroom::utils {

enum class ResampleFilter { Box, Bilinear, Nearest };

struct Tap {
    int index;
    double weight;  // > 0; not normalised (callers divide by the weights they used)
};

struct AxisTaps {
    std::vector<int> first;  // output pixel o reads taps[first[o] .. first[o + 1])
    std::vector<Tap> taps;
    std::vector<int> nearest;  // source pixel whose centre is nearest to o's centre

    const Tap* begin(int o) const { return taps.data() + first[std::size_t(o)]; }
    const Tap* end(int o) const { return taps.data() + first[std::size_t(o) + 1]; }
};

// Box: the overlap (in source pixels) of the output pixel's footprint with
// each source pixel, so an integer factor N averages N source pixels with
// weight 1 each. Bilinear: the two source pixels around the output centre
// (clamped at the border). Nearest: the source pixel containing the centre.
AxisTaps axisTaps(int inSize, int outSize, ResampleFilter filter);

}  // namespace darkroom::utils
