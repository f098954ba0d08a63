#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/io/eight_bit_rows.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "eight_bit_rows.h"
#include "srgb_code.h"

#include <algorithm>
#include <cstdint>
#include <cstring>

HWY_BEFORE_NAMESPACE();
namespace darkroom::io {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DF = hn::ScalableTag<float>;
using DI = hn::RebindToSigned<DF>;
using D8 = hn::Rebind<std::uint8_t, DF>;
using VF = hn::Vec<DF>;
using VI = hn::Vec<DI>;

// The sRGB code of each lane, as SrgbCodeTable::code with encodeColourValue's
// ends: NaN and v <= 0 -> 0, v >= 1 -> 255. The code at the start of the
// value's bucket, then one step per threshold at or below the value
// (positive floats order as their bits do, so the compares are on integers).
VI ColourCodes(VF v, const SrgbCodeTable& t) {
    const DF df;
    const DI di;
    const auto inRange = hn::RebindMask(di, hn::And(hn::Gt(v, hn::Zero(df)), hn::Lt(v, hn::Set(df, 1.0f))));
    const auto saturated = hn::RebindMask(di, hn::Ge(v, hn::Set(df, 1.0f)));
    if (hn::AllFalse(di, inRange)) return hn::IfThenElseZero(saturated, hn::Set(di, 255));
    const VI bits = hn::BitCast(di, v);
    const VI bucket = hn::IfThenElseZero(inRange, hn::ShiftRight<SrgbCodeTable::kBucketShift>(bits));
    const auto* starts = reinterpret_cast<const std::int32_t*>(t.bucketStartWide);
    const auto* thresholds = reinterpret_cast<const std::int32_t*>(t.threshold);
    const VI one = hn::Set(di, 1);
    VI code = hn::GatherIndex(di, starts, bucket);
    for (;;) {
        // threshold[256] is 1.0f, above every lane in range: the loop ends.
        const VI next = hn::GatherIndex(di, thresholds, hn::Add(code, one));
        const auto step = hn::AndNot(hn::Lt(bits, next), inRange);
        if (hn::AllFalse(di, step)) break;
        code = hn::Add(code, hn::IfThenElseZero(step, one));
    }
    return hn::IfThenElse(saturated, hn::Set(di, 255), hn::IfThenElseZero(inRange, code));
}

// encodeAlphaValue per lane: lround(v * 255) in (0, 1) as floor(m + 0.5)
// with m = v * 255 in float, i.e. trunc(m) plus one where m - trunc(m) >=
// 0.5 (both exact in float for m < 256), NaN and v <= 0 -> 0, v >= 1 -> 255.
VI AlphaCodes(VF v) {
    const DF df;
    const DI di;
    const auto inRange = hn::RebindMask(di, hn::And(hn::Gt(v, hn::Zero(df)), hn::Lt(v, hn::Set(df, 1.0f))));
    const auto saturated = hn::RebindMask(di, hn::Ge(v, hn::Set(df, 1.0f)));
    const VF m = hn::Mul(hn::IfThenElseZero(hn::RebindMask(df, inRange), v), hn::Set(df, 255.0f));
    const VI whole = hn::ConvertTo(di, m);  // truncates; m >= 0
    const auto roundUp = hn::RebindMask(di, hn::Ge(hn::Sub(m, hn::ConvertTo(df, whole)), hn::Set(df, 0.5f)));
    const VI code = hn::Add(whole, hn::IfThenElseZero(roundUp, hn::Set(di, 1)));
    return hn::IfThenElse(saturated, hn::Set(di, 255), hn::IfThenElseZero(inRange, code));
}

// Lanes(DF) pixels from x: each channel's codes, narrowed to bytes and
// stored interleaved.
void EncodePixels(const float* const* planes, int n, bool alpha, std::size_t x, unsigned char* out) {
    const DF df;
    const D8 d8;
    const SrgbCodeTable& t = srgbCodeTable();
    hn::Vec<D8> c[4];
    for (int k = 0; k < n; ++k) {
        const VF v = hn::LoadU(df, planes[k] + x);
        c[k] = hn::DemoteTo(d8, alpha && k == n - 1 ? AlphaCodes(v) : ColourCodes(v, t));
    }
    switch (n) {
        case 1: hn::StoreU(c[0], d8, out); break;
        case 2: hn::StoreInterleaved2(c[0], c[1], d8, out); break;
        case 3: hn::StoreInterleaved3(c[0], c[1], c[2], d8, out); break;
        default: hn::StoreInterleaved4(c[0], c[1], c[2], c[3], d8, out); break;
    }
}

void EncodeRow(const float* const* planes, int n, bool alpha, std::size_t w, unsigned char* out) {
    const DF df;
    const std::size_t lanes = hn::Lanes(df);
    std::size_t x = 0;
    for (; x + lanes <= w; x += lanes) EncodePixels(planes, n, alpha, x, out + x * std::size_t(n));
    if (x == w) return;
    // The row's last pixels through a whole vector of copies (zeros beyond
    // the row: background, never stored).
    constexpr std::size_t kMaxLanes = 64;
    alignas(64) float tail[4][kMaxLanes] = {};
    alignas(64) unsigned char codes[4 * kMaxLanes];
    const float* tailPlanes[4];
    for (int k = 0; k < n; ++k) {
        std::memcpy(tail[k], planes[k] + x, (w - x) * sizeof(float));
        tailPlanes[k] = tail[k];
    }
    EncodePixels(tailPlanes, n, alpha, 0, codes);
    std::memcpy(out + x * std::size_t(n), codes, (w - x) * std::size_t(n));
}

}  // namespace HWY_NAMESPACE
}  // namespace darkroom::io
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace darkroom::io {
HWY_EXPORT(EncodeRow);
void encodeEightBitRow(const float* const* planes, int channels, bool alpha, std::size_t width, unsigned char* out) {
    HWY_DYNAMIC_DISPATCH(EncodeRow)(planes, channels, alpha, width, out);
}
}  // namespace darkroom::io
#endif
