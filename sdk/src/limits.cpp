#include <darkroom/error.h>
#include <darkroom/limits.h>

#include <array>
#include <atomic>

namespace darkroom {

namespace {

constexpr std::uint64_t kGiB = 1ull << 30;

// Defaults generous enough for real data (a 16384² G-buffer, a 8 GiB mesh),
// small enough that a forged header cannot take the machine down.
std::array<std::atomic<std::uint64_t>, 5>& values() {
    static std::array<std::atomic<std::uint64_t>, 5> v{
        std::uint64_t(1) << 28,  // ImagePixels: 16384 x 16384
        8 * kGiB,                // InputBytes
        8 * kGiB,                // DecodedBytes
        0,                       // NodeBytes: no limit
        0,                       // NodeMilliseconds: no limit
    };
    return v;
}

std::size_t indexOf(Limit which) {
    const auto i = static_cast<std::size_t>(which);
    if (i >= values().size()) throw Error("unknown limit " + std::to_string(i));
    return i;
}

}  // namespace

std::uint64_t limit(Limit which) { return values()[indexOf(which)].load(std::memory_order_relaxed); }

void setLimit(Limit which, std::uint64_t value) { values()[indexOf(which)].store(value, std::memory_order_relaxed); }

const char* limitOption(Limit which) {
    switch (which) {
    case Limit::ImagePixels: return "--max-image-pixels";
    case Limit::InputBytes: return "--max-input-bytes";
    case Limit::DecodedBytes: return "--max-decoded-bytes";
    case Limit::NodeBytes: return "--max-node-memory";
    case Limit::NodeMilliseconds: return "--max-node-seconds";
    }
    return "?";
}

void checkImagePixels(std::uint64_t width, std::uint64_t height, const std::string& where) {
    const std::uint64_t cap = limit(Limit::ImagePixels);
    // width * height > cap, without overflow.
    const bool over = width != 0 && height > cap / width;
    if (over)
        throw InputError(where + ": " + std::to_string(width) + " x " + std::to_string(height) +
                         " pixels exceed the limit of " + std::to_string(cap) + " pixels (" +
                         limitOption(Limit::ImagePixels) + ")");
}

void checkBytes(Limit which, std::uint64_t bytes, const std::string& where, const std::string& what) {
    const std::uint64_t cap = limit(which);
    if (cap != 0 && bytes > cap)
        throw InputError(where + ": " + what + " of " + std::to_string(bytes) + " bytes exceeds the limit of " +
                         std::to_string(cap) + " bytes (" + limitOption(which) + ")");
}

}  // namespace darkroom
