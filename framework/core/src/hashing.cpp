#include "hashing.h"

#include <variant>

namespace darkroom::hashing {

std::uint64_t hashChannels(const std::vector<ChannelDesc>& channels) {
    std::uint64_t h = 0x243f6a8885a308d3ULL;
    for (const auto& c : channels) h = mix(mixText(h, c.name), std::uint64_t(c.type));
    return h;
}

namespace {
std::uint64_t mixVec(std::uint64_t h, const Vec3& v) { return mixDouble(mixDouble(mixDouble(h, v.x), v.y), v.z); }
}  // namespace

std::uint64_t hashMetadata(const BufferMetadata& m) {
    std::uint64_t h = 0x13198a2e03707344ULL;
    if (m.camera) {
        const Camera& c = *m.camera;
        h = mixVec(mixVec(mixVec(mix(h, 1), c.position), c.forward), c.up);
        h = mix(mixDouble(mixDouble(h, c.fovYDegrees), c.viewHeight), std::uint64_t(c.projection));
        h = mix(mix(h, std::uint64_t(std::uint32_t(c.width))), std::uint64_t(std::uint32_t(c.height)));
    }
    for (const auto& [k, v] : m.attributes) h = mixText(mixText(h, k), v);
    return h;
}

std::uint64_t hashValue(const Value& v) {
    const auto& s = v.storage();
    std::uint64_t h = mix(0xa4093822299f31d0ULL, s.index());
    return std::visit(
        [&](const auto& x) -> std::uint64_t {
            using T = std::decay_t<decltype(x)>;
            if constexpr (std::is_same_v<T, std::monostate>) return h;
            else if constexpr (std::is_same_v<T, bool>) return mix(h, x ? 1 : 0);
            else if constexpr (std::is_same_v<T, std::int64_t>) return mix(h, std::uint64_t(x));
            else if constexpr (std::is_same_v<T, double>) return mixDouble(h, x);
            else if constexpr (std::is_same_v<T, std::string>) return mixText(h, x);
            else if constexpr (std::is_same_v<T, Color>)
                return mixDouble(mixDouble(mixDouble(mixDouble(h, x.r), x.g), x.b), x.a);
            else if constexpr (std::is_same_v<T, Vec3>) return mixVec(h, x);
            else if constexpr (std::is_same_v<T, Row>) {
                // By content: a reader that runs again and reads the same
                // entry leaves the nodes fed its row cached.
                for (const RowCell& c : x.cells()) h = mixText(mixText(h, c.column), c.text);
                return mix(h, x.cells().size());
            } else return mix(h, std::uint64_t(reinterpret_cast<std::uintptr_t>(x.get())));
        },
        s);
}

}  // namespace darkroom::hashing
