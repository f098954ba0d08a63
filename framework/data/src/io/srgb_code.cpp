#include "srgb_code.h"

#include <darkroom/srgb.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <vector>

namespace darkroom::io {

namespace {

constexpr std::uint32_t kOne = 0x3f800000u;  // the bits of 1.0f
constexpr int kBucketShift = SrgbCodeTable::kBucketShift;

int exactCode(std::uint32_t bits) {
    return int(std::lround(linearToSrgb(std::bit_cast<float>(bits)) * 255.0f));
}

struct Tables {
    // threshold[k]: bits of the least float in (0, 1) whose code is >= k
    // (k = 1..255); kOne when none is (past the last value below 1).
    std::array<std::uint32_t, 257> threshold{};
    // The code of the first float of each bucket of 2^kBucketShift floats.
    std::vector<std::uint8_t> bucketStart;
    std::vector<std::uint32_t> bucketStartWide;

    Tables() {
        for (int k = 1; k <= 255; ++k) {
            std::uint32_t lo = 1, hi = kOne;  // answer in [lo, hi]; hi = none
            while (lo < hi) {
                const std::uint32_t mid = lo + (hi - lo) / 2;
                if (exactCode(mid) >= k) hi = mid;
                else lo = mid + 1;
            }
            threshold[std::size_t(k)] = lo;
        }
        threshold[256] = kOne;  // no code 256: stops the stepping
        bucketStart.resize((kOne >> kBucketShift) + 1);
        for (std::size_t b = 0; b < bucketStart.size(); ++b) {
            const std::uint32_t first = std::max<std::uint32_t>(1, std::uint32_t(b) << kBucketShift);
            bucketStart[b] = std::uint8_t(first >= kOne ? 255 : exactCode(first));
        }
        bucketStartWide.assign(bucketStart.begin(), bucketStart.end());
    }
};

}  // namespace

const SrgbCodeTable& srgbCodeTable() {
    static const Tables t;
    static const SrgbCodeTable view{t.threshold.data(), t.bucketStart.data(), t.bucketStartWide.data()};
    return view;
}

}  // namespace darkroom::io
