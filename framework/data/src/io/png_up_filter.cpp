#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/io/png_up_filter.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "png_up_filter.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstring>
#include <vector>

HWY_BEFORE_NAMESPACE();
namespace darkroom::io {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// row[i] -= prior[i], wrapping, for i < n.
void SubtractRow(unsigned char* row, const unsigned char* prior, std::size_t n) {
    const hn::ScalableTag<std::uint8_t> d;
    const std::size_t lanes = hn::Lanes(d);
    std::size_t i = 0;
    for (; i + lanes <= n; i += lanes)
        hn::StoreU(hn::Sub(hn::LoadU(d, row + i), hn::LoadU(d, prior + i)), d, row + i);
    for (; i < n; ++i) row[i] = static_cast<unsigned char>(row[i] - prior[i]);
}

}  // namespace HWY_NAMESPACE
}  // namespace darkroom::io
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace darkroom::io {
HWY_EXPORT(SubtractRow);

void filterUpInPlace(unsigned char* rows, std::size_t rowBytes, int height) {
    if (height <= 0 || rowBytes == 0) return;
    const std::size_t n = rowBytes - 1;
    auto row = [&](int y) { return rows + std::size_t(y) * rowBytes; };
    // Each band filters its rows bottom-up, so a row is subtracted from the
    // row above before that one changes. A band's first row needs the row
    // above it as it was, which the band above may already have filtered:
    // those rows are copied first.
    constexpr int kBand = 32;
    const int bands = (height + kBand - 1) / kBand;
    std::vector<unsigned char> above(std::size_t(bands) * n);
    for (int b = 1; b < bands; ++b) std::memcpy(above.data() + std::size_t(b) * n, row(b * kBand - 1) + 1, n);
    tbb::parallel_for(0, bands, [&](int b) {
        const int begin = b * kBand, end = std::min(height, begin + kBand);
        for (int y = end - 1; y > begin; --y) HWY_DYNAMIC_DISPATCH(SubtractRow)(row(y) + 1, row(y - 1) + 1, n);
        if (b > 0) HWY_DYNAMIC_DISPATCH(SubtractRow)(row(begin) + 1, above.data() + std::size_t(b) * n, n);
        for (int y = begin; y < end; ++y) row(y)[0] = 2;
    });
}

}  // namespace darkroom::io
#endif
