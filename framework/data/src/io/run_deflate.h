#pragma once
// A deflate encoder for filtered PNG rows that finds only runs: a byte
// repeating the one before it (distance 1) or the pixel before it (distance
// `pixelBytes`), each block coded with its own Huffman tables (RFC 1951,
// dynamic blocks; a block that would not shrink is stored).
//
// Why not libdeflate alone: a colour-mapped render is mostly background, and
// libdeflate's fastest level still hashes every byte of a long run (4 ns a
// byte on the 2-core machine), which made deflating the zeros of a 2048²
// picture the largest cost of a --foreach entry after reading the EXR.
// Finding runs by comparing 8 bytes at a time skips them for almost nothing.
// What it gives up: back references farther than one pixel, so pictures
// with repeated texture come out larger (docs/performance.md, "Codecs").
#include <cstddef>
#include <cstdint>
#include <vector>

namespace darkroom::io {

// The zlib stream (RFC 1950: header, deflate blocks, Adler-32) of `data`.
// `pixelBytes` is the second run distance tried (1 to 8; the PNG's bytes per
// pixel).
std::vector<unsigned char> runDeflateZlib(const unsigned char* data, std::size_t size, int pixelBytes);

}  // namespace darkroom::io
