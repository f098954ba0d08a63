#pragma once
// Length-limited canonical Huffman codes for a deflate encoder (RFC 1951,
// 3.2.2). Internal to the data library.
#include <array>
#include <cstdint>
#include <vector>

namespace darkroom::io {

struct HuffmanCode {
    std::vector<std::uint8_t> lengths;  // per symbol, 0 = unused
    std::vector<std::uint16_t> codes;   // per symbol, bit-reversed for LSB-first writing
};

using Histogram19 = std::array<std::uint32_t, 19>;

// A complete prefix code for `count` symbols of the given frequencies, no
// code longer than `limit` bits. At least two symbols get a code (symbols 0
// and 1 when fewer are used), since inflaters refuse an incomplete code.
// Lengths come from Huffman's algorithm; when one exceeds the limit the
// frequencies are halved (rounding up, so none vanishes) until none does,
// which flattens the tree: cheap, and within a fraction of a percent of
// optimal on picture histograms.
HuffmanCode huffmanCode(const std::uint32_t* frequencies, int count, int limit);

}  // namespace darkroom::io
