#pragma once
// 64-bit hashes of the things a node's cache key is made of.
#include <darkroom/buffer.h>
#include <darkroom/value.h>
#include <darkroom/core/hash_mix.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace darkroom::hashing {

std::uint64_t hashChannels(const std::vector<ChannelDesc>& channels);
std::uint64_t hashMetadata(const BufferMetadata& m);
// A value input: its type and contents (an image by the buffer's address; the
// evaluator keys images by what is read instead).
std::uint64_t hashValue(const Value& v);

}  // namespace darkroom::hashing
