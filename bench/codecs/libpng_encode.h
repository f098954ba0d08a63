#pragma once
// libpng's own encoder with a zlib level and one filter set: the writer as it
// was before libdeflate (level 2, "up"), and zlib's candidates, to compare
// against (docs/performance.md, "Codecs"). Benchmark code only.
#include <string>

namespace darkroom::bench {

// `filters`: libpng's PNG_FILTER_* mask (several bits: libpng's adaptive choice).
std::string libpngEncode(const unsigned char* rgba, int width, int height, int channels, int zlibLevel, int filters);

}  // namespace darkroom::bench
