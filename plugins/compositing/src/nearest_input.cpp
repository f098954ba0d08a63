#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/nearest_input.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "nearest_input.h"

#include <cmath>
#include <limits>

HWY_BEFORE_NAMESPACE();
namespace darkroom::compositing {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void NearestInputs(const float* const* depths, int inputs, int width, int* winner) {
    const hn::ScalableTag<float> df;
    const hn::RebindToSigned<decltype(df)> di;
    const int lanes = int(hn::Lanes(df));
    const float inf = std::numeric_limits<float>::infinity();
    int x = 0;
    for (; x + lanes <= width; x += lanes) {
        auto best = hn::Set(df, inf);
        auto who = hn::Set(di, -1);
        for (int k = 0; k < inputs; ++k) {
            const auto z = hn::LoadU(df, depths[k] + x);
            // Strictly nearer: ties keep the lower index.
            const auto nearer = hn::And(hn::Lt(z, best), hn::Lt(hn::Abs(z), hn::Set(df, inf)));
            best = hn::IfThenElse(nearer, z, best);
            who = hn::IfThenElse(hn::RebindMask(di, nearer), hn::Set(di, k), who);
        }
        hn::StoreU(who, di, winner + x);
    }
    for (; x < width; ++x) {
        float best = inf;
        int who = -1;
        for (int k = 0; k < inputs; ++k) {
            const float z = depths[k][x];
            if (z < best && std::isfinite(z)) {
                best = z;
                who = k;
            }
        }
        winner[x] = who;
    }
}

}  // namespace HWY_NAMESPACE
}  // namespace darkroom::compositing
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace darkroom::compositing {
HWY_EXPORT(NearestInputs);
void nearestInputs(const float* const* depths, int inputs, int width, int* winner) {
    HWY_DYNAMIC_DISPATCH(NearestInputs)(depths, inputs, width, winner);
}
}  // namespace darkroom::compositing
#endif
