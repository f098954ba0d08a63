#pragma once
// The per-pixel work of ColorMapping: the range of the data and the lookup
// of a value in the colour table. The per-pixel code (color_mapping.cpp,
// scalar_range.cpp) and the SIMD code (map_simd.cpp) do the same operations
// in the same order, so they give the same bits.
#include <darkroom/colormap.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace darkroom::colormapping {

// Entries in the lookup table: linear interpolation between them stays far
// below 8-bit resolution for every preset, and both ends are exact samples.
constexpr int kTableSize = 4096;

struct MapJob {
    const float* depth = nullptr;  // nullptr: no background
    const Color* table = nullptr;  // kTableSize entries
    // Per channel (R, G, B), entries k and k + 1 of the table side by side
    // in one 64-bit word (k below kTableSize - 1): one gather fetches both.
    const std::uint64_t* pairs[3] = {nullptr, nullptr, nullptr};
    Color nan;                     // for NaN values, and every value without a range
    float alpha = 1.0f;
    bool haveRange = false;
    double low = 0, high = 0;
    float* out[4] = {nullptr, nullptr, nullptr, nullptr};  // R, G, B, A
};

// MapJob::pairs for a table of kTableSize entries: 3 * (kTableSize - 1) words.
std::vector<std::uint64_t> tablePairs(const std::vector<Color>& table);

// The colour of value v at pixel i.
Color mapValue(const MapJob& job, std::size_t i, double v);
// Pixels [begin, end) of a float32 channel with the best SIMD instructions of
// the CPU; returns end, or begin when the span is shorter than a vector.
std::size_t mapSpan(const MapJob& job, const float* values, std::size_t begin, std::size_t end);

// Finite minimum and maximum of values[begin, end) over pixels whose depth
// (when given) is not +inf. found = false when there is none.
struct MinMax {
    float low, high;
    bool found;
};
MinMax rangeSpan(const float* values, const float* depth, std::size_t begin, std::size_t end);

}  // namespace darkroom::colormapping
