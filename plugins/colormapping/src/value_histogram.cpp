#include "value_histogram.h"

#include <algorithm>

namespace darkroom::colormapping {

ValueHistogram::ValueHistogram(double low, double high)
    : low_(low), high_(high), scale_(high > low ? double(kBins) / (high - low) : 0.0), bins_(kBins, 0) {}

std::size_t ValueHistogram::binOf(double v) const {
    const double k = (v - low_) * scale_;
    return k <= 0 ? 0 : std::min(kBins - 1, std::size_t(k));
}

ValueHistogram::Bin ValueHistogram::binOfRank(std::uint64_t rank, std::uint64_t below) const {
    const double width = (high_ - low_) / double(kBins);
    std::uint64_t seen = below;
    for (std::size_t k = 0; k < kBins; ++k) {
        if (seen + bins_[k] > rank)
            return {k, low_ + double(k) * width, k + 1 == kBins ? high_ : low_ + double(k + 1) * width, seen};
        seen += bins_[k];
    }
    return {kBins - 1, high_, high_, seen};
}

}  // namespace darkroom::colormapping
