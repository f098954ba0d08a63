#pragma once
// A 64-bit digest of everything a buffer holds: size, every channel (name,
// type and the bits of every pixel, channels taken in name order so that a
// pass may append or replace a channel in another position), and metadata
// (camera fields in hexadecimal floating point, attributes but `source`, the
// path it was read from). Two buffers with
// the same digest are, for a test, bit for bit the same picture.
#include <darkroom/buffer.h>

#include <cstdint>
#include <string>

namespace darkroom::test {

std::uint64_t digest(const Buffer& b);
std::uint64_t digest(const std::string& bytes);
std::string hex(std::uint64_t v);

}  // namespace darkroom::test
