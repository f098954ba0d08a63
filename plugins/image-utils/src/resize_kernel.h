#pragma once
// Resize's per-pixel rules (resize.cpp) and a SIMD version of them for a row
// of output pixels at a time (resize_simd.cpp): the same double-precision
// sums in the same tap order, so both give the same bits.
#include "resample_taps.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace darkroom::utils {

// One output row's view of the source: the y taps of the row, the x taps of
// every column, and the source image's width.
struct ResizeRow {
    const AxisTaps* tx;
    const Tap* yBegin;
    const Tap* yEnd;
    int sourceWidth;
    int outputWidth;
};

// The source pixel (flat index) that gives output pixel x its depth and ids:
// the nearest finite depth of the footprint (ties: the first in scan order),
// else `fallback`.
std::size_t nearestDepthSource(const ResizeRow& row, const float* depth, int x, std::size_t fallback);
// The filtered value of output pixel x: weighted mean of the finite samples
// (by alpha too when weightBy is given and some alpha is positive), NaN when
// there is none.
float resampleAt(const ResizeRow& row, const float* src, const float* weightBy, int x);

// The x taps of every output column padded to the same count (weight 0 =
// padding, which points at a valid pixel), laid out tap-major for vectors.
struct PaddedTaps {
    int count = 0;
    std::vector<std::int32_t> index;  // [k * outputs + x]
    std::vector<double> weight;       // [k * outputs + x]
};
PaddedTaps padTaps(const AxisTaps& a, int outputs);

// The whole row with the best SIMD instructions of the CPU; each returns the
// output width, or 0 when the row is shorter than a vector. Flat source
// indices must fit an int32.
int resampleRow(const ResizeRow& row, const PaddedTaps& px, const float* src, const float* weightBy, float* out);
// source[x] = nearestDepthSource(row, depth, x, fallback[x]).
int nearestDepthRow(const ResizeRow& row, const PaddedTaps& px, const float* depth, const std::int32_t* fallback,
                    std::int32_t* source);
// out[x] = src[source[x]] for 4-byte values.
int gatherRow(const std::uint32_t* src, const std::int32_t* source, int width, std::uint32_t* out);

}  // namespace darkroom::utils
