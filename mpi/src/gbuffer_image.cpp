#include <darkroom/error.h>
#include <darkroom/mpi/gbuffer_image.h>

#include <cstring>

namespace darkroom::mpi {

int GBufferImage::channelIndex(std::string_view name) const {
    for (std::size_t c = 0; c < channels.size(); ++c)
        if (channels[c].name == name) return int(c);
    return -1;
}

float* GBufferImage::floatPlane(std::string_view name) {
    const int c = channelIndex(name);
    if (c < 0 || channels[std::size_t(c)].type != ChannelType::Float32) return nullptr;
    return reinterpret_cast<float*>(planes[std::size_t(c)].data());
}

std::uint32_t* GBufferImage::uintPlane(std::string_view name) {
    const int c = channelIndex(name);
    if (c < 0 || channels[std::size_t(c)].type != ChannelType::UInt32) return nullptr;
    return planes[std::size_t(c)].data();
}

GBufferImage GBufferImage::from(const Buffer& buffer) {
    GBufferImage out;
    out.width = buffer.width();
    out.height = buffer.height();
    out.channels = buffer.channels();
    out.metadata = buffer.metadata();
    const std::size_t n = buffer.pixelCount();
    for (const auto& c : out.channels) {
        const void* src = c.type == ChannelType::Float32 ? static_cast<const void*>(buffer.hostFloat(c.name))
                                                         : static_cast<const void*>(buffer.hostUInt(c.name));
        if (!src) throw Error("G-buffer channel '" + c.name + "' cannot be read");
        std::vector<std::uint32_t> plane(n);
        std::memcpy(plane.data(), src, n * 4);
        out.planes.push_back(std::move(plane));
    }
    return out;
}

std::shared_ptr<WritableBuffer> GBufferImage::toBuffer() const {
    auto out = makeCpuBuffer(width, height, channels);
    const std::size_t n = pixelCount();
    for (std::size_t c = 0; c < channels.size(); ++c) {
        void* dst = channels[c].type == ChannelType::Float32 ? static_cast<void*>(out->writeFloat(channels[c].name))
                                                             : static_cast<void*>(out->writeUInt(channels[c].name));
        std::memcpy(dst, planes[c].data(), n * 4);
    }
    out->metadata() = metadata;
    return out;
}

}  // namespace darkroom::mpi
