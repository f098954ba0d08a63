#pragma once
// An 8-bit PNG in memory: the rows filtered here, the whole filtered image
// deflated at once, by libdeflate (Debian's libdeflate-dev, faster than zlib
// at every level for the same size) or by the run encoder (run_deflate.h),
// which the writer uses (docs/performance.md, "Codecs").
// Internal to the data library; the benchmark (bench/codecs) and the unit
// tests compile it in to compare filters and levels.
#include <cstddef>
#include <string>

namespace darkroom::io {

// PNG's row filters (PNG spec, 9.2), and libpng's adaptive choice per row:
// the filter with the least sum of absolute (signed) differences.
enum class PngFilter { None, Sub, Up, Average, Paeth, Adaptive };

// Which deflate encoder: libdeflate's at a level, or the run encoder
// (run_deflate.h), which finds only repeats of the previous byte or pixel.
enum class Deflater { Libdeflate, Runs };

struct PngEncoding {
    PngFilter filter = PngFilter::Up;
    int level = 1;  // libdeflate's level, 0 (stored) to 12; unused by Runs
    Deflater deflater = Deflater::Libdeflate;
};

struct PngPixels {
    int width = 0, height = 0;
    int channels = 0;                       // 1 grey, 2 grey+alpha, 3 RGB, 4 RGBA
    const unsigned char* data = nullptr;    // interleaved 8-bit, rows top to bottom
};

// The PNG file: IHDR, gAMA, sRGB, cHRM (what libpng's
// png_set_sRGB_gAMA_and_cHRM wrote before), IDAT, IEND. Throws
// darkroom::Error (without a path) when memory runs out.
std::string encodePng(const PngPixels& pixels, const PngEncoding& encoding);

// The same file from rows already filtered (`size` = filteredSize(pixels)
// bytes laid out as filterRows lays them out; `pixels.data` is not read, and
// `encoding.filter` is not applied again).
std::string encodeFilteredPng(const PngPixels& pixels, const unsigned char* filtered, std::size_t size,
                              const PngEncoding& encoding);

// The filtered rows (a filter-type byte, then the row), as deflated, into
// `out` of filteredSize(pixels) bytes. Exposed for the tests.
std::size_t filteredSize(const PngPixels& pixels);
void filterRows(const PngPixels& pixels, PngFilter filter, unsigned char* out);

}  // namespace darkroom::io
