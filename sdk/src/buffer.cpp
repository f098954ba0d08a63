#include <darkroom/buffer.h>
#include <darkroom/error.h>

#include <cstring>
#include <set>

namespace darkroom {

const char* toString(ChannelType t) { return t == ChannelType::Float32 ? "float32" : "uint32"; }

Buffer::~Buffer() = default;

bool Buffer::hasChannel(std::string_view name) const { return channelType(name).has_value(); }

std::optional<ChannelType> Buffer::channelType(std::string_view name) const {
    for (const auto& c : channels())
        if (c.name == name) return c.type;
    return std::nullopt;
}

std::vector<std::string> Buffer::channelNames() const {
    std::vector<std::string> out;
    for (const auto& c : channels()) out.push_back(c.name);
    return out;
}

static std::string describeMissing(const Buffer& b, std::string_view channel, const char* type) {
    std::string have;
    for (const auto& c : b.channels()) {
        if (!have.empty()) have += ", ";
        have += c.name + " (" + toString(c.type) + ")";
    }
    return "expected a " + std::string(type) + " channel '" + std::string(channel) +
           "' but the image has " + (have.empty() ? std::string("no channels") : have);
}

const float* Buffer::requireFloat(std::string_view channel) const {
    if (const float* p = hostFloat(channel)) return p;
    throw Error(describeMissing(*this, channel, "float32"));
}

const std::uint32_t* Buffer::requireUInt(std::string_view channel) const {
    if (const std::uint32_t* p = hostUInt(channel)) return p;
    throw Error(describeMissing(*this, channel, "uint32"));
}

float* WritableBuffer::requireFloat(std::string_view channel) {
    if (float* p = hostFloat(channel)) return p;
    throw Error(describeMissing(*this, channel, "float32"));
}

std::uint32_t* WritableBuffer::requireUInt(std::string_view channel) {
    if (std::uint32_t* p = hostUInt(channel)) return p;
    throw Error(describeMissing(*this, channel, "uint32"));
}

namespace {

// Planar CPU storage: one contiguous 4-byte array per channel.
class CpuBuffer final : public WritableBuffer {
public:
    CpuBuffer(int w, int h, std::vector<ChannelDesc> ch) : w_(w), h_(h), channels_(std::move(ch)) {
        if (w < 0 || h < 0) throw Error("image size must not be negative");
        std::set<std::string> seen;
        for (const auto& c : channels_)
            if (!seen.insert(c.name).second)
                throw Error("channel '" + c.name + "' appears twice in one image");
        data_.resize(channels_.size());
        for (auto& d : data_) d.assign(std::size_t(w) * std::size_t(h), 0u);
    }
    int width() const override { return w_; }
    int height() const override { return h_; }
    const std::vector<ChannelDesc>& channels() const override { return channels_; }
    const BufferMetadata& metadata() const override { return meta_; }
    BufferMetadata& metadata() override { return meta_; }

    const float* hostFloat(std::string_view n) const override {
        const int i = find(n, ChannelType::Float32);
        return i < 0 ? nullptr : reinterpret_cast<const float*>(data_[i].data());
    }
    const std::uint32_t* hostUInt(std::string_view n) const override {
        const int i = find(n, ChannelType::UInt32);
        return i < 0 ? nullptr : data_[i].data();
    }
    float* hostFloat(std::string_view n) override {
        const int i = find(n, ChannelType::Float32);
        return i < 0 ? nullptr : reinterpret_cast<float*>(data_[i].data());
    }
    std::uint32_t* hostUInt(std::string_view n) override {
        const int i = find(n, ChannelType::UInt32);
        return i < 0 ? nullptr : data_[i].data();
    }

private:
    int find(std::string_view n, ChannelType t) const {
        for (std::size_t i = 0; i < channels_.size(); ++i)
            if (channels_[i].name == n) return channels_[i].type == t ? int(i) : -1;
        return -1;
    }
    int w_, h_;
    std::vector<ChannelDesc> channels_;
    BufferMetadata meta_;
    // uint32 storage for both types: same size and alignment as float.
    std::vector<std::vector<std::uint32_t>> data_;
};

}  // namespace

std::shared_ptr<WritableBuffer> makeCpuBuffer(int width, int height, std::vector<ChannelDesc> channels) {
    return std::make_shared<CpuBuffer>(width, height, std::move(channels));
}

bool identical(const Buffer& a, const Buffer& b) {
    if (a.width() != b.width() || a.height() != b.height() || a.channels() != b.channels() ||
        !(a.metadata() == b.metadata()))
        return false;
    const std::size_t bytes = a.pixelCount() * 4;
    for (const auto& c : a.channels()) {
        const void* pa = c.type == ChannelType::Float32 ? static_cast<const void*>(a.hostFloat(c.name))
                                                        : static_cast<const void*>(a.hostUInt(c.name));
        const void* pb = c.type == ChannelType::Float32 ? static_cast<const void*>(b.hostFloat(c.name))
                                                        : static_cast<const void*>(b.hostUInt(c.name));
        if (bytes && std::memcmp(pa, pb, bytes) != 0) return false;
    }
    return true;
}

}  // namespace darkroom
