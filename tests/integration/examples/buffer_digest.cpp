#include "buffer_digest.h"

#include <algorithm>
#include <cstdio>
#include <cstring>

namespace darkroom::test {

namespace {

struct Hasher {
    std::uint64_t h = 0x6a09e667f3bcc908ULL;
    void word(std::uint64_t v) {
        // splitmix64 step over the running state.
        std::uint64_t z = (h ^ v) + 0x9e3779b97f4a7c15ULL;
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        h = z ^ (z >> 31);
    }
    void bytes(const void* p, std::size_t n) {
        const auto* c = static_cast<const unsigned char*>(p);
        std::size_t i = 0;
        for (; i + 8 <= n; i += 8) {
            std::uint64_t v;
            std::memcpy(&v, c + i, 8);
            word(v);
        }
        std::uint64_t tail = 0;
        std::memcpy(&tail, c + i, n - i);
        word(tail ^ (std::uint64_t(n) << 56));
    }
    void text(const std::string& s) { bytes(s.data(), s.size()); }
};

std::string hexFloat(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%a", v);
    return buf;
}

}  // namespace

std::uint64_t digest(const Buffer& b) {
    Hasher h;
    h.word(std::uint64_t(b.width()));
    h.word(std::uint64_t(b.height()));
    std::vector<ChannelDesc> channels = b.channels();
    std::sort(channels.begin(), channels.end(),
              [](const ChannelDesc& x, const ChannelDesc& y) { return x.name < y.name; });
    const std::size_t bytes = b.pixelCount() * 4;
    for (const auto& c : channels) {
        h.text(c.name);
        h.word(std::uint64_t(c.type));
        const void* p = c.type == ChannelType::Float32 ? static_cast<const void*>(b.hostFloat(c.name))
                                                       : static_cast<const void*>(b.hostUInt(c.name));
        if (p && bytes) h.bytes(p, bytes);
    }
    const BufferMetadata& m = b.metadata();
    if (m.camera) {
        const Camera& c = *m.camera;
        std::string s;
        for (double v : {c.position.x, c.position.y, c.position.z, c.forward.x, c.forward.y, c.forward.z, c.up.x,
                         c.up.y, c.up.z, c.fovYDegrees, c.viewHeight})
            s += hexFloat(v) + ",";
        s += std::to_string(int(c.projection)) + "," + std::to_string(c.width) + "," + std::to_string(c.height);
        h.text(s);
    }
    for (const auto& [k, v] : m.attributes) {
        // Where the picture was read from (a product's path, under the
        // test's temporary folder) is no part of the picture.
        if (k == "source") continue;
        h.text(k);
        h.text(v);
    }
    return h.h;
}

std::uint64_t digest(const std::string& bytes) {
    Hasher h;
    h.bytes(bytes.data(), bytes.size());
    return h.h;
}

std::string hex(std::uint64_t v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(v));
    return buf;
}

}  // namespace darkroom::test
