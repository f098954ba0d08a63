// Per-target SIMD helpers of the SSAO kernels (Google Highway): 3-vectors of
// lanes, the per-pixel noise hash, a division-free cube root. Included once
// per target by each kernel's foreach_target expansion, hence the toggle guard
// instead of #pragma once.
//
// Every lane computes the same function of its own pixel whatever the vector
// width, with fused multiply-adds only where written (the plugin is compiled
// with -ffp-contract=off), so AVX2 and AVX-512 give identical bits.
#if defined(DARKROOM_SSAO_SIMD_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef DARKROOM_SSAO_SIMD_INL_H_
#undef DARKROOM_SSAO_SIMD_INL_H_
#else
#define DARKROOM_SSAO_SIMD_INL_H_
#endif

#include <hwy/highway.h>

#include <cstdint>

HWY_BEFORE_NAMESPACE();
namespace darkroom::ssao::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DF = hn::ScalableTag<float>;
using DI = hn::RebindToSigned<DF>;
using DU = hn::RebindToUnsigned<DF>;
using VF = hn::Vec<DF>;
using VI = hn::Vec<DI>;
using VU = hn::Vec<DU>;
using MF = hn::Mask<DF>;

struct V3 {
    VF x, y, z;
};

HWY_INLINE V3 Splat(DF d, float x, float y, float z) { return {hn::Set(d, x), hn::Set(d, y), hn::Set(d, z)}; }
HWY_INLINE V3 Add(V3 a, V3 b) { return {hn::Add(a.x, b.x), hn::Add(a.y, b.y), hn::Add(a.z, b.z)}; }
HWY_INLINE V3 Sub(V3 a, V3 b) { return {hn::Sub(a.x, b.x), hn::Sub(a.y, b.y), hn::Sub(a.z, b.z)}; }
HWY_INLINE V3 Scale(V3 a, VF s) { return {hn::Mul(a.x, s), hn::Mul(a.y, s), hn::Mul(a.z, s)}; }
// a + b * s
HWY_INLINE V3 AddScaled(V3 a, V3 b, VF s) { return {hn::MulAdd(b.x, s, a.x), hn::MulAdd(b.y, s, a.y), hn::MulAdd(b.z, s, a.z)}; }
// a - b * s
HWY_INLINE V3 SubScaled(V3 a, V3 b, VF s) {
    return {hn::NegMulAdd(b.x, s, a.x), hn::NegMulAdd(b.y, s, a.y), hn::NegMulAdd(b.z, s, a.z)};
}
HWY_INLINE VF Dot(V3 a, V3 b) { return hn::MulAdd(a.x, b.x, hn::MulAdd(a.y, b.y, hn::Mul(a.z, b.z))); }
HWY_INLINE V3 Cross(V3 a, V3 b) {
    return {hn::MulSub(a.y, b.z, hn::Mul(a.z, b.y)), hn::MulSub(a.z, b.x, hn::Mul(a.x, b.z)),
            hn::MulSub(a.x, b.y, hn::Mul(a.y, b.x))};
}
HWY_INLINE V3 Select(MF m, V3 a, V3 b) {
    return {hn::IfThenElse(m, a.x, b.x), hn::IfThenElse(m, a.y, b.y), hn::IfThenElse(m, a.z, b.z)};
}
// a / |a|, or a where |a| = 0.
HWY_INLINE V3 Normalize(DF d, V3 a) {
    const VF len = hn::Sqrt(Dot(a, a));
    const VF inv = hn::IfThenElse(hn::Gt(len, hn::Zero(d)), hn::Div(hn::Set(d, 1.0f), len), hn::Set(d, 1.0f));
    return Scale(a, inv);
}

// `count` floats from p (all lanes when count >= lanes), the rest `fill`:
// never reads past p + count.
HWY_INLINE VF LoadPartial(DF d, const float* p, int count, float fill) {
    if (count >= int(hn::Lanes(d))) return hn::LoadU(d, p);
    alignas(64) float buf[64];
    for (int i = 0; i < int(hn::Lanes(d)); ++i) buf[i] = i < count ? p[i] : fill;
    return hn::Load(d, buf);
}

// The hash of noise.h, lane by lane: identical values to pixelNoise().
HWY_INLINE VU Mix32(VU v) {
    const DU du;
    v = hn::Xor(v, hn::ShiftRight<16>(v));
    v = hn::Mul(v, hn::Set(du, 0x7feb352dU));
    v = hn::Xor(v, hn::ShiftRight<15>(v));
    v = hn::Mul(v, hn::Set(du, 0x846ca68bU));
    return hn::Xor(v, hn::ShiftRight<16>(v));
}
// pixelNoise(x, y, seed, stream) for the pixels x (one a lane) of row y;
// rowHash = mix32(y + 0x632be5ab), streamHash = mix32(seed * 0x85ebca6b + stream).
HWY_INLINE VF PixelNoise(DF d, VU x, std::uint32_t rowHash, std::uint32_t streamHash) {
    const DU du;
    VU h = Mix32(hn::Xor(hn::Mul(x, hn::Set(du, 0x9e3779b9U)), hn::Set(du, rowHash)));
    h = Mix32(hn::Xor(h, hn::Set(du, streamHash)));
    const VI top = hn::BitCast(DI(), hn::ShiftRight<8>(h));
    return hn::Mul(hn::ConvertTo(d, top), hn::Set(d, 1.0f / 16777216.0f));
}

// Half resolution: the rotation noise u of the computed pixels (even x and
// y) is stratified over each 2 x 2 block of them, (k + u) / 4 with k from a
// 2 x 2 Bayer pattern of (x/2, y/2), so the blur, which spans at least two
// computed pixels each way, averages every quarter of the range (interleaved
// sampling). Each pixel's rotation stays uniform in [0, 1) and independent of
// its other noise (the step jitter is not stratified: tying the two together
// would bias the estimate).
HWY_INLINE VF Stratify(DF d, VU x, int y, VF u) {
    const DU du;
    const VF bx = hn::ConvertTo(d, hn::BitCast(DI(), hn::And(hn::ShiftRight<1>(x), hn::Set(du, 1u))));
    // Bayer: [0 2; 3 1].
    const VF two = hn::Set(d, 2.0f);
    const VF k = ((y >> 1) & 1) != 0 ? hn::NegMulAdd(two, bx, hn::Set(d, 3.0f)) : hn::Mul(two, bx);
    return hn::Mul(hn::Add(k, u), hn::Set(d, 0.25f));
}

// x^(1/3) for x in [0.01, 1]: three Newton steps on x^(-1/3) from the
// classic exponent-bits guess (no division), relative error < 1e-6.
HWY_INLINE VF CubeRoot(DF d, VF x) {
    const DI di;
    // Guess: bits(x^-1/3) ~ 4/3 bits(1) - bits(x) / 3.
    const VI bits = hn::BitCast(di, x);
    const VF third = hn::Set(d, 1.0f / 3.0f);
    const VI guess = hn::Sub(hn::Set(di, 0x54a2fa8c),
                             hn::ConvertTo(di, hn::Mul(hn::ConvertTo(d, bits), third)));
    VF r = hn::BitCast(d, guess);
    const VF four = hn::Set(d, 4.0f);
    for (int i = 0; i < 3; ++i) {
        const VF r3 = hn::Mul(hn::Mul(r, r), r);
        r = hn::Mul(hn::Mul(r, hn::NegMulAdd(x, r3, four)), third);
    }
    return hn::Mul(x, hn::Mul(r, r));
}

}  // namespace darkroom::ssao::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // DARKROOM_SSAO_SIMD_INL_H_
