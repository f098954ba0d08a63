// OpenEXR's zip pre-pass undone (see exr_zip.h).
#include "exr_zip.h"

namespace darkroom::io {

namespace {

// The predictor stored d[i] = t[i] - t[i-1] + 128 (mod 256) for i > 0 and
// t[0] as it was, so t is the running sum of d less 128 per step. The sum is
// one long dependency chain, the cost of the whole pass; the second half's
// chain starts from t[half - 1], which a plain byte sum (vectorised by the
// compiler) gives without walking the first chain, so both halves are
// walked at once below.
std::uint8_t prefixEnd(const std::uint8_t* d, std::size_t count) {
    unsigned sum = 0;
    for (std::size_t i = 0; i < count; ++i) sum += d[i];
    // Every step after the first subtracts 128; modulo 256 that is 128 per
    // odd number of steps.
    return std::uint8_t(sum + ((count - 1) & 1u) * 128u);
}

}  // namespace

void undoZipPrepass(const std::uint8_t* inflated, std::size_t n, std::uint8_t* out) {
    if (n == 0) return;
    const std::size_t half = (n + 1) / 2;  // the even-offset bytes; the odd ones follow
    const std::uint8_t* d = inflated;
    std::uint8_t even = d[0];
    std::uint8_t odd = half < n ? std::uint8_t(prefixEnd(d, half) + d[half] - 128u) : 0;
    out[0] = even;
    if (half < n) out[1] = odd;
    // Pairs (2k, 2k + 1) for k >= 1 while both exist; n odd leaves one even byte.
    const std::size_t pairs = n / 2;
    for (std::size_t k = 1; k < pairs; ++k) {
        even = std::uint8_t(even + d[k] - 128u);
        odd = std::uint8_t(odd + d[half + k] - 128u);
        out[2 * k] = even;
        out[2 * k + 1] = odd;
    }
    if (n % 2 == 1 && half > 1) out[n - 1] = std::uint8_t(even + d[half - 1] - 128u);
}

}  // namespace darkroom::io
