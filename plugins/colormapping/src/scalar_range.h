#pragma once
// Finite min/max of a scalar channel, skipping background pixels.
#include <darkroom/buffer.h>
#include <darkroom/context.h>

#include <string>

namespace darkroom {

// Reads a float32 or uint32 channel as numbers.
struct ScalarChannel {
    const float* f = nullptr;
    const std::uint32_t* u = nullptr;
    double operator[](std::size_t i) const { return f ? double(f[i]) : double(u[i]); }
};

struct ScalarRange {
    double low = 0, high = 0;
    bool found = false;  // false when no pixel had a finite value
};

// Over pixels whose value is finite (and positive, when `positiveOnly`: the
// range of a log scale) and whose depth (when `depth` is given) is not +inf.
// Row-parallel; the result does not depend on the split.
ScalarRange finiteRange(Context& ctx, const ScalarChannel& s, const float* depth, int width, int height,
                        bool positiveOnly = false);

}  // namespace darkroom
