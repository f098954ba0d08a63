#pragma once
// OpenEXR's ZIP and ZIPS chunks hold a zlib stream of the chunk's bytes after
// a pre-pass that helps deflate: the bytes are split into two halves (those at
// even offsets first, then those at odd offsets: the low and high bytes of a
// half float end up apart), and then each byte is replaced by its difference
// to the one before plus 128 (OpenEXR's ImfZip.cpp, the file layout document).
// Undone here for the direct EXR decoder (exr_direct.h). Internal to the data
// library; the unit tests compile it in.
#include <cstddef>
#include <cstdint>

namespace darkroom::io {

// `inflated` (n bytes, as inflated from the chunk) back into the chunk's
// bytes in `out` (n bytes, not overlapping): the predictor undone and the
// halves interleaved again, in one pass.
void undoZipPrepass(const std::uint8_t* inflated, std::size_t n, std::uint8_t* out);

}  // namespace darkroom::io
