#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/io/background_spans.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "background_spans.h"

#include <algorithm>

HWY_BEFORE_NAMESPACE();
namespace darkroom::io {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void Mark(const float* s, std::size_t n, std::uint8_t* flags) {
    const hn::ScalableTag<float> d;
    const std::size_t lanes = hn::Lanes(d);
    const auto zero = hn::Zero(d);
    for (std::size_t begin = 0, k = 0; begin < n; begin += kBackgroundSpan, ++k) {
        const std::size_t end = std::min(n, begin + kBackgroundSpan);
        bool background = true;
        std::size_t i = begin;
        for (; background && i + lanes <= end; i += lanes)
            background = hn::AllFalse(d, hn::Gt(hn::LoadU(d, s + i), zero));  // NaN > 0 is false
        for (; background && i < end; ++i) background = !(s[i] > 0.0f);
        flags[k] = background ? 1 : 0;
    }
}

}  // namespace HWY_NAMESPACE
}  // namespace darkroom::io
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace darkroom::io {
HWY_EXPORT(Mark);
void markBackgroundSpans(const float* s, std::size_t n, std::uint8_t* flags) {
    HWY_DYNAMIC_DISPATCH(Mark)(s, n, flags);
}
}  // namespace darkroom::io
#endif
