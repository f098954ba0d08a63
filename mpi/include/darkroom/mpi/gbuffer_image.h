#pragma once
// A G-buffer as depth compositing works on it: planar channels of 4-byte
// values (float32 or uint32, moved as bits, never converted) that the caller
// may adjust before compositing (e.g. turn local primitive ids into global
// ones), with the metadata of the buffer it came from.
#include <darkroom/buffer.h>

#include <cstdint>
#include <memory>
#include <string_view>
#include <vector>

namespace darkroom::mpi {

struct GBufferImage {
    int width = 0, height = 0;
    std::vector<ChannelDesc> channels;
    // planes[c] holds width * height values of channel c, rows top to bottom.
    std::vector<std::vector<std::uint32_t>> planes;
    BufferMetadata metadata;

    std::size_t pixelCount() const { return std::size_t(width) * std::size_t(height); }
    // Index of a channel, or -1.
    int channelIndex(std::string_view name) const;
    float* floatPlane(std::string_view name);
    std::uint32_t* uintPlane(std::string_view name);

    // Copies every channel and the metadata of `buffer`.
    static GBufferImage from(const Buffer& buffer);
    // A buffer with the same channels (in order), pixels and metadata.
    std::shared_ptr<WritableBuffer> toBuffer() const;
};

}  // namespace darkroom::mpi
