#pragma once
// Which input is nearest at each pixel of a row.

namespace darkroom::compositing {

// winner[x] = the index of the input whose depth depths[k][x] is smallest and
// finite, ties to the lower index; -1 where no input has a finite depth
// (+inf, -inf and NaN never win). Vectors of pixels with the best SIMD
// instructions of the CPU.
void nearestInputs(const float* const* depths, int inputs, int width, int* winner);

}  // namespace darkroom::compositing
