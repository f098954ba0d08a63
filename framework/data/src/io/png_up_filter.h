#pragma once
// PNG's "up" filter (PNG spec, 9.2) in place, on rows laid out as a PNG's
// filtered data: a filter-type byte, then the row's bytes. The writer encodes
// its 8-bit codes straight into such rows (eight_bit.h) and filters them
// where they lie: one buffer instead of two, and the subtraction in SIMD
// (Highway) over bands of rows in parallel.
#include <cstddef>

namespace darkroom::io {

// rows[y * rowBytes] becomes 2 (up); bytes 1..rowBytes-1 of row y become
// their difference from row y - 1's (row 0 keeps its bytes: the row above
// the first is zero).
void filterUpInPlace(unsigned char* rows, std::size_t rowBytes, int height);

}  // namespace darkroom::io
