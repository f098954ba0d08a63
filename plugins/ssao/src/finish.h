#pragma once
#include "frame.h"

namespace darkroom::ssao {

// Rows [y0, y1) of the output channel (width floats a row) from the padded
// raw AO plane: clamp(1 - intensity (1 - AO), 0, 1)^power where the frame has
// a surface, 1 elsewhere.
void finishRows(const Frame& g, const float* raw, float intensity, float power, int y0, int y1, float* out);

}  // namespace darkroom::ssao
