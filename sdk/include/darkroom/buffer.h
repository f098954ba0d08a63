#pragma once
#include <darkroom/camera.h>
#include <darkroom/export.h>

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace darkroom {

enum class ChannelType : std::uint8_t { Float32, UInt32 };

DARKROOM_API const char* toString(ChannelType t);

struct ChannelDesc {
    std::string name;
    ChannelType type = ChannelType::Float32;
    bool operator==(const ChannelDesc&) const = default;
};

// Everything a buffer knows besides its pixels.
struct BufferMetadata {
    std::optional<Camera> camera;
    // Free-form, ordered key/value pairs: units ("units.Z" = "m"), provenance
    // ("source" = file or node), colour-map hints ("colormap.Elevation" = path).
    std::map<std::string, std::string> attributes;
    bool operator==(const BufferMetadata&) const = default;
};

// An immutable 2D image with named, typed channels. Channels are stored planar
// (one contiguous width*height array per channel), rows top to bottom.
//
// Buffers are published as shared_ptr<const Buffer>, so fan-out and caching are
// free. Pixel access goes through host*() which, for the CPU implementation,
// returns the storage itself; a future GPU-resident implementation maps on demand.
class DARKROOM_API Buffer {
public:
    virtual ~Buffer();

    virtual int width() const = 0;
    virtual int height() const = 0;
    virtual const std::vector<ChannelDesc>& channels() const = 0;
    virtual const BufferMetadata& metadata() const = 0;

    // Planar channel data on the host; nullptr when the channel is absent or
    // has another type.
    virtual const float* hostFloat(std::string_view channel) const = 0;
    virtual const std::uint32_t* hostUInt(std::string_view channel) const = 0;

    // Convenience (non-virtual).
    std::size_t pixelCount() const { return std::size_t(width()) * std::size_t(height()); }
    bool hasChannel(std::string_view name) const;
    std::optional<ChannelType> channelType(std::string_view name) const;
    std::vector<std::string> channelNames() const;
    // Like hostFloat but throws darkroom::Error naming the channel and the
    // channels that do exist.
    const float* requireFloat(std::string_view channel) const;
    const std::uint32_t* requireUInt(std::string_view channel) const;
};

// A buffer being filled by the filter that allocated it. Once published with
// Context::setOutput it is only seen through shared_ptr<const Buffer>.
class DARKROOM_API WritableBuffer : public Buffer {
public:
    virtual float* hostFloat(std::string_view channel) = 0;
    virtual std::uint32_t* hostUInt(std::string_view channel) = 0;
    virtual BufferMetadata& metadata() = 0;
    using Buffer::hostFloat;
    using Buffer::hostUInt;
    using Buffer::metadata;

    float* requireFloat(std::string_view channel);
    std::uint32_t* requireUInt(std::string_view channel);
};

using BufferPtr = std::shared_ptr<const Buffer>;

// Allocates a CPU buffer with zero-initialised channels. Filters normally call
// Context::allocate instead, which lets the host choose the storage.
DARKROOM_API std::shared_ptr<WritableBuffer> makeCpuBuffer(int width, int height,
                                                           std::vector<ChannelDesc> channels);

// True when both buffers have the same size, channels, metadata and bitwise
// identical pixels (NaNs compare equal to NaNs with the same bits).
DARKROOM_API bool identical(const Buffer& a, const Buffer& b);

}  // namespace darkroom
