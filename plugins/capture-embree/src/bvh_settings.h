#pragma once
// How Embree builds a scene's BVH, chosen by the scene's size and the memory
// at hand. Every choice gives the same pixels (the ray-triangle test and the
// tie rule do not depend on the BVH; tests/test_bvh_settings.cpp); they trade
// build time, memory and trace time, as measured in docs/performance.md
// ("Capture ingest") with bench/capture/bench_bvh_settings.
#include <cstddef>
#include <cstdint>

namespace darkroom::embree {

struct BvhSettings {
    // High: SAH (spatial splits where Embree has them); Medium: SAH; Low: a
    // two-level scene whose geometries Embree's Morton builder builds.
    enum class Quality : std::uint8_t { Low, Medium, High };
    Quality quality = Quality::High;
    // RTC_SCENE_FLAG_COMPACT: leaves index the shared vertex arrays instead
    // of holding their own copy of each triangle.
    bool compact = false;
    // Surfaces of more primitives are handed to Embree as several
    // geometries of at most this many (0: whole). Low's Morton builder then
    // sorts one piece at a time instead of the whole mesh, which takes its
    // temporary (8 bytes per primitive: morton codes) off the peak; the
    // pixels do not change (the pieces keep the object's primitive order,
    // and the capture maps them back to object and primitive ids).
    std::size_t piecePrimitives = 0;
};

// From this many primitives on, a scene is "big": below it the BVH's memory
// is small beside any machine's, and the best BVH is built.
inline constexpr std::size_t kBigScenePrimitives = std::size_t(4) << 20;

// Bytes per primitive Embree peaks at while building a big scene of
// triangles (on top of the scene's own arrays), measured on a 33.5M-triangle
// height field: Low + compact 53.7 whole, 47.4 in pieces on 2 threads (more
// threads sort more pieces at once, up to the whole mesh's 8 bytes of
// morton codes: the bound stays), Medium + compact 34.8.
inline constexpr double kLowCompactPeakBytes = 56.0;

// Low's pieces: 2M triangles, 16 MB of morton codes each; the two-level
// builder builds about one piece per thread at a time.
inline constexpr std::size_t kLowPiecePrimitives = std::size_t(1) << 21;

// Small scenes: High. Big ones: compact, and Low (several times faster to
// build, in pieces of kLowPiecePrimitives) when its peak takes at most half
// of `availableBytes`, else Medium (a third less memory).
BvhSettings bvhSettingsFor(std::size_t primitives, std::uint64_t availableBytes);

// bvhSettingsFor(primitives, the memory this machine has available now).
BvhSettings bvhSettingsFor(std::size_t primitives);

// MemAvailable from /proc/meminfo; 0 when it cannot be read.
std::uint64_t availableMemoryBytes();

}  // namespace darkroom::embree
