#include "luma.h"

#include <darkroom/srgb.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>

namespace darkroom::fxaa {

namespace {

// sRGB encoding tabulated over s = sqrt(linear): in that variable the curve
// is smooth down to 0 (the linear toe becomes 12.92 s^2), so linear
// interpolation between 4096 entries is accurate to ~1e-7 while costing a
// sqrt instead of a pow per channel.
constexpr int kEntries = kEncodeEntries;

const std::array<float, kEntries + 1>& encodingTable() {
    static const auto table = [] {
        std::array<float, kEntries + 1> t{};
        for (int i = 0; i <= kEntries; ++i) {
            const double s = double(i) / kEntries;
            t[std::size_t(i)] = std::min(1.0f, linearToSrgb(float(s * s)));
        }
        t[kEntries] = 1.0f;
        return t;
    }();
    return table;
}

inline float encode(const std::array<float, kEntries + 1>& t, float c) {
    // NaN never gets here (callers check blendable first); clamp handles +-inf.
    c = std::clamp(c, 0.0f, 1.0f);
    const float s = std::sqrt(c) * float(kEntries);
    const int i = std::min(int(s), kEntries - 1);
    const float f = s - float(i);
    return t[std::size_t(i)] + f * (t[std::size_t(i) + 1] - t[std::size_t(i)]);
}

inline float lumaOf(const std::array<float, kEntries + 1>& t, float r, float g, float b) {
    return 0.299f * encode(t, r) + 0.587f * encode(t, g) + 0.114f * encode(t, b);
}

}  // namespace

const float* encodeTable() { return encodingTable().data(); }

const std::uint64_t* encodePairs() {
    static const auto pairs = [] {
        const auto& t = encodingTable();
        std::array<std::uint64_t, kEntries> p{};
        for (std::size_t i = 0; i < p.size(); ++i) {
            const float two[2] = {t[i], t[i + 1]};
            std::memcpy(&p[i], two, sizeof two);  // t[i] in the first (lower-addressed) float
        }
        return p;
    }();
    return pairs.data();
}

float perceptualLuma(float r, float g, float b) { return lumaOf(encodingTable(), r, g, b); }

void computeLuma(const float* r, const float* g, const float* b, const float* alpha, float* luma,
                 std::size_t begin, std::size_t end) {
    const auto& t = encodingTable();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (std::size_t i = begin; i < end; ++i)
        luma[i] = blendable(r[i], g[i], b[i], alpha, i) ? lumaOf(t, r[i], g[i], b[i]) : nan;
}

}  // namespace darkroom::fxaa
