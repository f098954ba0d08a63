#include <darkroom/buffer.h>
#include <darkroom/error.h>
#include <darkroom/channel_text.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <map>
#include <mutex>
#include <new>
#include <string_view>
#include <unordered_map>

#include <sys/mman.h>

namespace darkroom {

const char* toString(ChannelType t) { return t == ChannelType::Float32 ? "float32" : "uint32"; }

namespace {
std::atomic<std::uint64_t> g_nextPlaneId{1};
}  // namespace

Plane::Plane() : id_(g_nextPlaneId.fetch_add(1, std::memory_order_relaxed)) {}
Plane::~Plane() = default;

HostPlane::HostPlane(void* storage, std::size_t pixels, std::function<void(void*)> release)
    : storage_(storage), pixels_(pixels), release_(std::move(release)) {}

HostPlane::~HostPlane() {
    if (release_) release_(storage_);
}

namespace {

// A plane of at least a huge page (2 MiB on x86-64) is mapped on its own,
// aligned to one and advised onto huge pages: passes that walk a column strip
// touch one 4 KiB page per row, more than the TLB holds, and reading a frame
// takes one page fault per 2 MiB instead of 512. Fresh anonymous memory is
// zero, so `zero` costs nothing. Null where it cannot be mapped so.
constexpr std::size_t kHugePage = std::size_t(2) << 20;

void* mapHugePages(std::size_t bytes, std::size_t& mapped) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if (bytes < kHugePage) return nullptr;
    const std::size_t used = (bytes + kHugePage - 1) / kHugePage * kHugePage;
    const std::size_t span = used + kHugePage;
    void* m = ::mmap(nullptr, span, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (m == MAP_FAILED) return nullptr;
    const auto base = reinterpret_cast<std::uintptr_t>(m);
    const std::uintptr_t start = (base + kHugePage - 1) / kHugePage * kHugePage;
    if (start > base) ::munmap(m, start - base);
    if (base + span > start + used) ::munmap(reinterpret_cast<void*>(start + used), base + span - start - used);
    (void)::madvise(reinterpret_cast<void*>(start), used, MADV_HUGEPAGE);
    mapped = used;
    return reinterpret_cast<void*>(start);
#else
    (void)bytes;
    (void)mapped;
    return nullptr;
#endif
}

// Mappings of released planes kept for the next plane of the same mapped
// size: a reader called once per --foreach entry (EXR, PNG planes) would
// otherwise map fresh memory each time, and the kernel's faults, zeroing and
// unmapping of it took a fifth of a colour-mapping batch's CPU (perf,
// docs/performance.md "Batch shading"). Bounded: what exceeds kIdleCap is
// unmapped. (Host contexts allocate from the framework's plane pool
// instead; this serves code that has no context, such as the readers.)
// A comparator of this file's own: the map's code then stays internal to the
// SDK instead of exporting std::multimap instantiations (the ABI check).
struct MappedSizeLess {
    bool operator()(std::size_t a, std::size_t b) const { return a < b; }
};

class MappingRecycler {
public:
    static MappingRecycler& shared() {
        static MappingRecycler* r = new MappingRecycler();  // never destroyed: planes may outlive statics
        return *r;
    }
    void* take(std::size_t mapped) {
        std::lock_guard<std::mutex> lock(mutex_);
        // The most recently released of that size: the likeliest still in
        // the caches (equal sizes are kept in the order they came back).
        const auto [first, last] = idle_.equal_range(mapped);
        if (first == last) return nullptr;
        const auto it = std::prev(last);
        void* p = it->second;
        idle_.erase(it);
        idleBytes_ -= mapped;
        return p;
    }
    void release(void* p, std::size_t mapped) {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            if (idleBytes_ + mapped <= kIdleCap) {
                idle_.emplace(mapped, p);
                idleBytes_ += mapped;
                return;
            }
        }
        ::munmap(p, mapped);
    }

private:
    // The framework's plane pool draws its large planes from here too
    // (framework/core/src/plane_pool.cpp): the cap is the pool's.
    static constexpr std::size_t kIdleCap = std::size_t(1) << 30;
    std::mutex mutex_;
    std::multimap<std::size_t, void*, MappedSizeLess> idle_;
    std::size_t idleBytes_ = 0;
};

}  // namespace

std::shared_ptr<HostPlane> newHostPlane(std::size_t pixels, bool zero) {
    const std::size_t bytes = std::max<std::size_t>(pixels, 1) * 4;
    std::size_t mapped = 0;
    void* h = nullptr;
    if (bytes >= kHugePage) {
        mapped = (bytes + kHugePage - 1) / kHugePage * kHugePage;
        h = MappingRecycler::shared().take(mapped);
        if (h && zero) std::memset(h, 0, bytes);  // fresh mappings come zeroed; recycled ones do not
    }
    if (!h) h = mapHugePages(bytes, mapped);
    if (h)
        return std::make_shared<HostPlane>(h, pixels,
                                           [mapped](void* s) { MappingRecycler::shared().release(s, mapped); });
    void* p = zero ? std::calloc(bytes, 1) : std::malloc(bytes);
    if (!p) throw std::bad_alloc();
    return std::make_shared<HostPlane>(p, pixels, [](void* s) { std::free(s); });
}

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
    return "expected a " + std::string(type) + " channel '" + std::string(channel) + "' but the image has " +
           channelListText(b, true);
}

const float* Buffer::requireFloat(std::string_view channel) const {
    if (const float* p = hostFloat(channel)) return p;
    throw Error(describeMissing(*this, channel, "float32"));
}

const std::uint32_t* Buffer::requireUInt(std::string_view channel) const {
    if (const std::uint32_t* p = hostUInt(channel)) return p;
    throw Error(describeMissing(*this, channel, "uint32"));
}

static std::string describeNotWritable(const Buffer& b, std::string_view channel, ChannelType t) {
    const auto have = b.channelType(channel);
    if (have && *have == t)
        return "channel '" + std::string(channel) +
               "' is shared with another buffer and cannot be written; list it among the fresh channels of "
               "Context::derive to replace it";
    return describeMissing(b, channel, toString(t));
}

namespace {

// Planar host storage: one shared plane per channel.
class HostBuffer final : public WritableBuffer {
public:
    HostBuffer(int w, int h) : w_(w), h_(h) {
        if (w < 0 || h < 0) throw Error("image size must not be negative");
    }
    int width() const override { return w_; }
    int height() const override { return h_; }
    const std::vector<ChannelDesc>& channels() const override { return channels_; }
    const BufferMetadata& metadata() const override { return meta_; }
    BufferMetadata& metadata() override { return meta_; }

    const float* hostFloat(std::string_view n) const override {
        const int i = find(n, ChannelType::Float32);
        return i < 0 ? nullptr : static_cast<const float*>(planes_[std::size_t(i)]->data());
    }
    const std::uint32_t* hostUInt(std::string_view n) const override {
        const int i = find(n, ChannelType::UInt32);
        return i < 0 ? nullptr : static_cast<const std::uint32_t*>(planes_[std::size_t(i)]->data());
    }
    PlanePtr plane(std::string_view n) const override {
        const int i = indexOf(n);
        return i < 0 ? nullptr : planes_[std::size_t(i)];
    }
    float* writeFloat(std::string_view n) override {
        if (void* p = writable(find(n, ChannelType::Float32))) return static_cast<float*>(p);
        throw Error(describeNotWritable(*this, n, ChannelType::Float32));
    }
    std::uint32_t* writeUInt(std::string_view n) override {
        if (void* p = writable(find(n, ChannelType::UInt32))) return static_cast<std::uint32_t*>(p);
        throw Error(describeNotWritable(*this, n, ChannelType::UInt32));
    }
    void setPlane(const ChannelDesc& c, PlanePtr p) override {
        if (!p) throw Error("channel '" + c.name + "': no plane given");
        if (p->pixels() != pixelCount())
            throw Error("channel '" + c.name + "': a plane of " + std::to_string(p->pixels()) +
                        " values does not fit a " + std::to_string(w_) + "x" + std::to_string(h_) + " image");
        if (const int i = indexOf(c.name); i >= 0) {
            channels_[std::size_t(i)] = c;
            planes_[std::size_t(i)] = std::move(p);
            return;
        }
        index_.emplace(c.name, channels_.size());
        channels_.push_back(c);
        planes_.push_back(std::move(p));
    }
    void removeChannel(std::string_view n) override {
        const int i = indexOf(n);
        if (i < 0) return;
        channels_.erase(channels_.begin() + std::ptrdiff_t(i));
        planes_.erase(planes_.begin() + std::ptrdiff_t(i));
        index_.clear();
        for (std::size_t k = 0; k < channels_.size(); ++k) index_.emplace(channels_[k].name, k);
    }

private:
    // By name through a hash index: an image of a million channels (a forged
    // .npz of shape (1, 1, 1000000)) is built in linear time, not quadratic.
    int indexOf(std::string_view n) const {
        const auto it = index_.find(n);
        return it == index_.end() ? -1 : int(it->second);
    }
    int find(std::string_view n, ChannelType t) const {
        const int i = indexOf(n);
        return i >= 0 && channels_[std::size_t(i)].type == t ? i : -1;
    }
    void* writable(int i) {
        if (i < 0) return nullptr;
        // Only a host plane nobody has sealed is writable: one this buffer was
        // given fresh by the allocator, never one shared from an input.
        auto* hp = dynamic_cast<const HostPlane*>(planes_[std::size_t(i)].get());
        return hp && !hp->sealed() ? const_cast<HostPlane*>(hp)->writableData() : nullptr;
    }
    int w_, h_;
    std::vector<ChannelDesc> channels_;
    std::vector<PlanePtr> planes_;
    struct NameHash {
        using is_transparent = void;
        std::size_t operator()(std::string_view s) const { return std::hash<std::string_view>{}(s); }
    };
    std::unordered_map<std::string, std::size_t, NameHash, std::equal_to<>> index_;  // name -> position in channels_
    BufferMetadata meta_;
};

}  // namespace

std::shared_ptr<WritableBuffer> makeHostBuffer(int width, int height) {
    return std::make_shared<HostBuffer>(width, height);
}

std::shared_ptr<WritableBuffer> makeCpuBuffer(int width, int height, std::vector<ChannelDesc> channels) {
    auto b = makeHostBuffer(width, height);
    for (const auto& c : channels) {
        // plane() looks up by hash (hasChannel() would scan the channels).
        if (b->plane(c.name)) throw Error("channel '" + c.name + "' appears twice in one image");
        b->setPlane(c, newHostPlane(b->pixelCount(), true));
    }
    return b;
}

void sealPlanes(const Buffer& b) {
    for (const auto& c : b.channels())
        if (auto* hp = dynamic_cast<const HostPlane*>(b.plane(c.name).get())) hp->seal();
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
        if (pa != pb && bytes && std::memcmp(pa, pb, bytes) != 0) return false;
    }
    return true;
}

}  // namespace darkroom
