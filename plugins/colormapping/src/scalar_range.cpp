#include "scalar_range.h"

#include "map_kernel.h"

#include <cmath>
#include <limits>
#include <mutex>

namespace darkroom {

ScalarRange finiteRange(Context& ctx, const ScalarChannel& s, const float* depth, int width, int height,
                        bool positiveOnly) {
    ScalarRange total;
    std::mutex mutex;
    ctx.parallelFor(0, height, 16, [&](int y0, int y1) {
        ScalarRange r;
        r.low = std::numeric_limits<double>::infinity();
        r.high = -r.low;
        const std::size_t begin = std::size_t(y0) * std::size_t(width), end = std::size_t(y1) * std::size_t(width);
        // A log scale's range is over positive values only: the plain loop.
        if (s.f && !positiveOnly) {
            const colormapping::MinMax m = colormapping::rangeSpan(s.f, depth, begin, end);
            r.found = m.found;
            r.low = m.low;
            r.high = m.high;
        } else {
            for (std::size_t i = begin; i < end; ++i) {
                if (depth && std::isinf(depth[i]) && depth[i] > 0) continue;
                const double v = s[i];
                if (!std::isfinite(v) || (positiveOnly && !(v > 0))) continue;
                r.found = true;
                r.low = std::min(r.low, v);
                r.high = std::max(r.high, v);
            }
        }
        if (!r.found) return;
        // min and max are order independent, so merging chunks in any order is deterministic.
        std::lock_guard<std::mutex> g(mutex);
        if (!total.found) {
            total = r;
        } else {
            total.low = std::min(total.low, r.low);
            total.high = std::max(total.high, r.high);
        }
    });
    return total;
}

}  // namespace darkroom
