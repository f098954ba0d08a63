#include "bvh_settings.h"

#include <fstream>
#include <string>

namespace darkroom::embree {

BvhSettings bvhSettingsFor(std::size_t primitives, std::uint64_t availableBytes) {
    // A capture renders many views of one scene, so a better BVH pays off
    // while the scene is small.
    if (primitives < kBigScenePrimitives) return {BvhSettings::Quality::High, false};
    // Big: the time to the first ray is the build's, and memory the limit.
    const double lowPeak = kLowCompactPeakBytes * double(primitives);
    if (lowPeak <= 0.5 * double(availableBytes)) return {BvhSettings::Quality::Low, true, kLowPiecePrimitives};
    return {BvhSettings::Quality::Medium, true};
}

BvhSettings bvhSettingsFor(std::size_t primitives) {
    if (primitives < kBigScenePrimitives) return bvhSettingsFor(primitives, 0);
    return bvhSettingsFor(primitives, availableMemoryBytes());
}

std::uint64_t availableMemoryBytes() {
    std::ifstream meminfo("/proc/meminfo");
    std::string line;
    while (std::getline(meminfo, line))
        if (line.rfind("MemAvailable:", 0) == 0) return std::stoull(line.substr(13)) * 1024;  // "<n> kB"
    return 0;
}

}  // namespace darkroom::embree
