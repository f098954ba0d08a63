#include "resample_taps.h"

#include <algorithm>
#include <cmath>

namespace darkroom::utils {

AxisTaps axisTaps(int inSize, int outSize, ResampleFilter filter) {
    AxisTaps a;
    const double scale = double(inSize) / double(outSize);  // source pixels per output pixel
    a.first.reserve(std::size_t(outSize) + 1);
    for (int o = 0; o < outSize; ++o) {
        a.first.push_back(int(a.taps.size()));
        const double centre = (o + 0.5) * scale;
        const int nearest = std::clamp(int(std::floor(centre)), 0, inSize - 1);
        a.nearest.push_back(nearest);
        if (filter == ResampleFilter::Nearest) {
            a.taps.push_back({nearest, 1.0});
        } else if (filter == ResampleFilter::Box) {
            const double lo = o * scale, hi = (o + 1) * scale;
            const int i1 = std::min(inSize, int(std::ceil(hi)));
            for (int i = std::max(0, int(std::floor(lo))); i < i1; ++i) {
                const double overlap = std::min(hi, double(i + 1)) - std::max(lo, double(i));
                // Footprint edges land on pixel edges up to rounding; ignore slivers.
                if (overlap > 1e-9) a.taps.push_back({i, overlap});
            }
        } else {
            const double u = std::clamp(centre - 0.5, 0.0, double(inSize - 1));
            const int i0 = int(std::floor(u));
            const double t = u - i0;
            if (t < 1.0) a.taps.push_back({i0, 1.0 - t});
            if (t > 0.0) a.taps.push_back({std::min(i0 + 1, inSize - 1), t});
        }
    }
    a.first.push_back(int(a.taps.size()));
    return a;
}

}  // namespace darkroom::utils
