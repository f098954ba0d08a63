#pragma once
// Percentiles of values spread over many images without holding them: the
// database range's `clip` (database_range.cpp) counts every entry's values
// into a histogram of [low, high], then counts again inside the bin that
// holds each wanted rank. Two levels of 2^16 bins find a percentile within
// (high - low) / 2^32 — far below the colour table's 4096 entries — even
// when an outlier stretches [low, high] (the case clipping is for).
#include <cstddef>
#include <cstdint>
#include <vector>

namespace darkroom::colormapping {

class ValueHistogram {
public:
    static constexpr std::size_t kBins = 1u << 16;

    ValueHistogram(double low, double high);
    // The bin of a value in [low, high]; values outside count in the end bins
    // (callers pass only values of the range, or of one bin of a coarser level).
    std::size_t binOf(double v) const;
    void add(double v) {
        ++bins_[binOf(v)];
        ++total_;
    }
    std::uint64_t count() const { return total_; }

    // Where the value of rank `rank` (0-based, in ascending order, counted
    // from this histogram's first bin, below which `below` values lie) lies:
    // the bin's edges, and the values below the bin.
    struct Bin {
        std::size_t index;
        double low, high;
        std::uint64_t below;
    };
    Bin binOfRank(std::uint64_t rank, std::uint64_t below = 0) const;

private:
    double low_, high_, scale_;
    std::vector<std::uint64_t> bins_;
    std::uint64_t total_ = 0;
};

}  // namespace darkroom::colormapping
