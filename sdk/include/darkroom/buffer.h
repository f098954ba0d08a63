#pragma once
#include <darkroom/camera.h>
#include <darkroom/export.h>

#include <atomic>
#include <cstdint>
#include <functional>
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

    ChannelDesc() = default;
    // Implicit, so a list of names reads as float channels: ctx.derive(in, {"R", "G", "B"}).
    ChannelDesc(std::string n, ChannelType t = ChannelType::Float32) : name(std::move(n)), type(t) {}
    ChannelDesc(const char* n, ChannelType t = ChannelType::Float32) : name(n), type(t) {}
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

// The pixels of one channel: width * height 4-byte values, rows top to bottom.
// A plane is immutable once its buffer is published and is shared, never
// copied, by every buffer that carries the channel: a pass that adds AO to a
// ten-channel G-buffer allocates one plane and shares the other ten.
//
// id() is unique in the process and never reused, so it identifies the
// contents: the host keys its cache on the ids of the planes a node read.
class DARKROOM_API Plane {
public:
    virtual ~Plane();
    Plane(const Plane&) = delete;
    Plane& operator=(const Plane&) = delete;

    // The values in host memory (CPU storage: the storage itself; a future
    // GPU-resident plane maps on demand).
    virtual const void* data() const = 0;
    virtual std::size_t pixels() const = 0;
    std::uint64_t id() const { return id_; }

protected:
    Plane();

private:
    std::uint64_t id_;
};

using PlanePtr = std::shared_ptr<const Plane>;

// A plane in host memory. Writable only until sealed; the host seals every
// plane of a buffer when the buffer is published, so a plane reached through
// an input is never written.
class DARKROOM_API HostPlane final : public Plane {
public:
    // Takes `storage` (pixels * 4 bytes, at least 4-byte aligned); `release`
    // gives it back when the last owner lets go (to a pool, or free()).
    HostPlane(void* storage, std::size_t pixels, std::function<void(void*)> release);
    ~HostPlane() override;

    const void* data() const override { return storage_; }
    std::size_t pixels() const override { return pixels_; }
    // nullptr once sealed.
    void* writableData() { return sealed_.load(std::memory_order_acquire) ? nullptr : storage_; }
    void seal() const { sealed_.store(true, std::memory_order_release); }
    bool sealed() const { return sealed_.load(std::memory_order_acquire); }

private:
    void* storage_;
    std::size_t pixels_;
    std::function<void(void*)> release_;
    mutable std::atomic<bool> sealed_{false};
};

// A plane of `pixels` values from the general heap, zero-filled when `zero`.
DARKROOM_API std::shared_ptr<HostPlane> newHostPlane(std::size_t pixels, bool zero = true);

// An immutable 2D image with named, typed channels held as shared planes.
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
    // The shared plane behind a channel (nullptr when absent). Handing it to
    // another buffer (WritableBuffer::setPlane) copies nothing.
    virtual PlanePtr plane(std::string_view channel) const = 0;

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

// A buffer being filled by the filter that allocated or derived it. Once
// published with Context::setOutput it is only seen through shared_ptr<const Buffer>.
//
// Reading goes through the Buffer interface, as for any buffer (also for the
// channels shared with an input); writing asks for writeFloat/writeUInt,
// which only a plane this buffer was given fresh allows.
class DARKROOM_API WritableBuffer : public Buffer {
public:
    // The pixels of a channel this buffer allocated, to fill. Throws
    // darkroom::Error saying why not when the channel is absent, has another
    // type, or is a plane shared with another buffer (list it among derive()'s
    // fresh channels to replace it).
    virtual float* writeFloat(std::string_view channel) = 0;
    virtual std::uint32_t* writeUInt(std::string_view channel) = 0;
    virtual BufferMetadata& metadata() = 0;
    using Buffer::metadata;
    // Makes `plane` (width * height values) the channel `channel.name`:
    // replaces a channel of that name in place, else appends it.
    virtual void setPlane(const ChannelDesc& channel, PlanePtr plane) = 0;
    // Removes a channel; no effect when absent.
    virtual void removeChannel(std::string_view name) = 0;
};

using BufferPtr = std::shared_ptr<const Buffer>;

// A host-memory buffer of the given size with no channels yet; add planes with
// setPlane. The host builds its buffers this way from its pool.
DARKROOM_API std::shared_ptr<WritableBuffer> makeHostBuffer(int width, int height);

// A host-memory buffer with zero-initialised planes from the general heap. For
// tests and tools; filters call Context::allocate or Context::derive instead,
// which take planes from the host's pool.
DARKROOM_API std::shared_ptr<WritableBuffer> makeCpuBuffer(int width, int height,
                                                           std::vector<ChannelDesc> channels);

// Seals every host plane of `b` (see HostPlane): after this nobody writes it.
DARKROOM_API void sealPlanes(const Buffer& b);

// True when both buffers have the same size, channels, metadata and bitwise
// identical pixels (NaNs compare equal to NaNs with the same bits).
DARKROOM_API bool identical(const Buffer& a, const Buffer& b);

}  // namespace darkroom
