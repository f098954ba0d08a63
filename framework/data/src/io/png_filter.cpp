// PNG's row filters (PNG spec, section 9): each byte becomes its difference
// from a prediction out of the byte to its left (a), above (b) and above-left
// (c); the decoder adds the prediction back. Smooth rendered images compress
// much better filtered; which filter is best is measured (docs/performance.md).
#include "png_encoder.h"

#include <cstdlib>
#include <cstring>
#include <vector>

namespace darkroom::io {

namespace {

using Row = const unsigned char*;

unsigned char paethPredictor(int a, int b, int c) {
    const int p = a + b - c;
    const int pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
    if (pa <= pb && pa <= pc) return static_cast<unsigned char>(a);
    return static_cast<unsigned char>(pb <= pc ? b : c);
}

// One row through one filter into `out` (row bytes, no type byte). `prior`
// is the row above, all zero for the first row (as the spec defines it).
void filterRow(PngFilter f, Row row, Row prior, std::size_t n, std::size_t bpp, unsigned char* out) {
    switch (f) {
    case PngFilter::None: std::memcpy(out, row, n); return;
    case PngFilter::Sub:
        for (std::size_t i = 0; i < n; ++i) out[i] = static_cast<unsigned char>(row[i] - (i >= bpp ? row[i - bpp] : 0));
        return;
    case PngFilter::Up:
        for (std::size_t i = 0; i < n; ++i) out[i] = static_cast<unsigned char>(row[i] - prior[i]);
        return;
    case PngFilter::Average:
        for (std::size_t i = 0; i < n; ++i)
            out[i] = static_cast<unsigned char>(row[i] - ((i >= bpp ? row[i - bpp] : 0) + prior[i]) / 2);
        return;
    default:  // Paeth (Adaptive never reaches here)
        for (std::size_t i = 0; i < bpp && i < n; ++i) out[i] = static_cast<unsigned char>(row[i] - prior[i]);
        for (std::size_t i = bpp; i < n; ++i)
            out[i] = static_cast<unsigned char>(row[i] - paethPredictor(row[i - bpp], prior[i], prior[i - bpp]));
        return;
    }
}

// libpng's heuristic: bytes read as signed, the least sum of magnitudes wins.
std::size_t cost(const unsigned char* filtered, std::size_t n) {
    std::size_t sum = 0;
    for (std::size_t i = 0; i < n; ++i) sum += std::size_t(std::abs(int(static_cast<signed char>(filtered[i]))));
    return sum;
}

}  // namespace

std::size_t filteredSize(const PngPixels& px) {
    return std::size_t(px.height) * (std::size_t(px.width) * std::size_t(px.channels) + 1);
}

void filterRows(const PngPixels& px, PngFilter filter, unsigned char* out) {
    const std::size_t bpp = std::size_t(px.channels), n = std::size_t(px.width) * bpp;
    const std::vector<unsigned char> zeros(n, 0);
    std::vector<unsigned char> trial(filter == PngFilter::Adaptive ? n : 0);
    for (std::size_t y = 0; y < std::size_t(px.height); ++y) {
        Row row = px.data + y * n, prior = y == 0 ? zeros.data() : row - n;
        unsigned char* dst = out + y * (n + 1);
        PngFilter chosen = filter;
        if (filter == PngFilter::Adaptive) {
            std::size_t best = ~std::size_t(0);
            for (PngFilter f : {PngFilter::None, PngFilter::Sub, PngFilter::Up, PngFilter::Average, PngFilter::Paeth}) {
                filterRow(f, row, prior, n, bpp, trial.data());
                const std::size_t c = cost(trial.data(), n);
                if (c < best) best = c, chosen = f;
            }
        }
        dst[0] = static_cast<unsigned char>(chosen);
        filterRow(chosen, row, prior, n, bpp, dst + 1);
    }
}

}  // namespace darkroom::io
