// OpenEXR's zip pre-pass undone (see exr_zip.h).
#include "exr_zip.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace darkroom::io {

namespace {

// The predictor stored d[0] as it was and d[i] = t[i] - t[i-1] + 128 (mod
// 256) after, so t is a running sum of d less 128 per step; seeding the sum
// with t[-1] = 128 makes the first step like the others. The sum is one long
// dependency chain, the cost of the whole pass; the second half's chain
// starts from t[half - 1], which a plain byte sum gives without walking the
// first chain, so both halves are walked at once and their bytes written
// interleaved as they come.
constexpr std::uint8_t kFirstSeed = 128;

#if defined(__SSE2__)

// Byte sums of 16 bytes at a time (psadbw), then the rest.
unsigned byteSum(const std::uint8_t* d, std::size_t count) {
    const __m128i zero = _mm_setzero_si128();
    __m128i acc = zero;
    std::size_t i = 0;
    for (; i + 16 <= count; i += 16)
        acc = _mm_add_epi64(acc, _mm_sad_epu8(_mm_loadu_si128(reinterpret_cast<const __m128i*>(d + i)), zero));
    unsigned sum = unsigned(_mm_cvtsi128_si32(acc)) + unsigned(_mm_cvtsi128_si32(_mm_unpackhi_epi64(acc, acc)));
    for (; i < count; ++i) sum += d[i];
    return sum;
}

// Running sums (mod 256) within 16 bytes: four shifted adds.
__m128i prefixSum16(__m128i x) {
    x = _mm_add_epi8(x, _mm_slli_si128(x, 1));
    x = _mm_add_epi8(x, _mm_slli_si128(x, 2));
    x = _mm_add_epi8(x, _mm_slli_si128(x, 4));
    return _mm_add_epi8(x, _mm_slli_si128(x, 8));
}

// The last byte in all 16 (SSE2 has no byte shuffle).
__m128i broadcastLast(__m128i x) {
    x = _mm_srli_si128(x, 15);
    x = _mm_unpacklo_epi8(x, x);
    x = _mm_unpacklo_epi16(x, x);
    return _mm_shuffle_epi32(x, 0);
}

// Pairs 16 at a time while both halves have 16 left; returns how many were
// done, with `even` and `odd` the chains' last values.
std::size_t undoPairsSimd(const std::uint8_t* d, std::size_t half, std::size_t pairs, std::uint8_t* out,
                          std::uint8_t& even, std::uint8_t& odd) {
    const __m128i bias = _mm_set1_epi8(char(0x80));  // x ^ 0x80 = x - 128 (mod 256)
    __m128i carryEven = _mm_set1_epi8(char(even)), carryOdd = _mm_set1_epi8(char(odd));
    std::size_t k = 0;
    for (; k + 16 <= pairs; k += 16) {
        const __m128i a = _mm_loadu_si128(reinterpret_cast<const __m128i*>(d + k));
        const __m128i b = _mm_loadu_si128(reinterpret_cast<const __m128i*>(d + half + k));
        const __m128i te = _mm_add_epi8(prefixSum16(_mm_xor_si128(a, bias)), carryEven);
        const __m128i to = _mm_add_epi8(prefixSum16(_mm_xor_si128(b, bias)), carryOdd);
        _mm_storeu_si128(reinterpret_cast<__m128i*>(out + 2 * k), _mm_unpacklo_epi8(te, to));
        _mm_storeu_si128(reinterpret_cast<__m128i*>(out + 2 * k + 16), _mm_unpackhi_epi8(te, to));
        carryEven = broadcastLast(te);
        carryOdd = broadcastLast(to);
    }
    even = std::uint8_t(_mm_cvtsi128_si32(carryEven));
    odd = std::uint8_t(_mm_cvtsi128_si32(carryOdd));
    return k;
}

#else

unsigned byteSum(const std::uint8_t* d, std::size_t count) {
    unsigned sum = 0;
    for (std::size_t i = 0; i < count; ++i) sum += d[i];
    return sum;
}

std::size_t undoPairsSimd(const std::uint8_t*, std::size_t, std::size_t, std::uint8_t*, std::uint8_t&,
                          std::uint8_t&) {
    return 0;
}

#endif

// t[count - 1]: the seed plus `count` steps of d - 128; modulo 256 the 128s
// add up to 128 per odd number of them.
std::uint8_t chainEnd(const std::uint8_t* d, std::size_t count) {
    return std::uint8_t(kFirstSeed + byteSum(d, count) + (count & 1u) * 128u);
}

}  // namespace

void undoZipPrepass(const std::uint8_t* inflated, std::size_t n, std::uint8_t* out) {
    if (n == 0) return;
    const std::uint8_t* d = inflated;
    const std::size_t half = (n + 1) / 2;  // the even-offset bytes; the odd ones follow
    const std::size_t pairs = n / 2;       // (2k, 2k + 1) with both present
    std::uint8_t even = kFirstSeed;
    std::uint8_t odd = chainEnd(d, half);
    std::size_t k = undoPairsSimd(d, half, pairs, out, even, odd);
    for (; k < pairs; ++k) {
        even = std::uint8_t(even + d[k] - 128u);
        odd = std::uint8_t(odd + d[half + k] - 128u);
        out[2 * k] = even;
        out[2 * k + 1] = odd;
    }
    if (n % 2 == 1) out[n - 1] = std::uint8_t(even + d[half - 1] - 128u);  // the last even byte has no odd one
}

}  // namespace darkroom::io
