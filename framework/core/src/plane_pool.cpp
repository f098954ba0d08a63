#include "plane_pool.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <new>

namespace darkroom {

namespace {

constexpr std::size_t kAlignment = 64;  // a cache line: SIMD loads never straddle one at a row start
// Planes of at least a huge page (2 MiB on x86-64) come from the SDK's
// mappings, which put them on huge pages (newHostPlane; why: acquireMapped).
constexpr std::size_t kHugePage = std::size_t(2) << 20;

std::size_t roundedBytes(std::size_t pixels) {
    const std::size_t b = std::max<std::size_t>(pixels, 1) * 4;
    return (b + kAlignment - 1) / kAlignment * kAlignment;
}

void* allocatePlane(std::size_t bytes) {
    void* p = std::aligned_alloc(kAlignment, bytes);
    if (!p) throw std::bad_alloc();
    return p;
}

// Fills in parallel in 1 MiB pieces: on fresh memory this spreads the page
// faults over the cores instead of taking them all on one.
void fill(void* p, std::size_t bytes, std::uint32_t word) {
    constexpr std::size_t piece = std::size_t(1) << 20;
    const std::size_t pieces = (bytes + piece - 1) / piece;
    auto body = [&](std::size_t k) {
        char* b = static_cast<char*>(p) + k * piece;
        const std::size_t n = std::min(piece, bytes - k * piece);
        if (word == 0) {
            std::memset(b, 0, n);
        } else {
            auto* w = reinterpret_cast<std::uint32_t*>(b);
            std::fill(w, w + n / 4, word);
        }
    };
    if (pieces <= 1) {
        if (pieces == 1) body(0);
        return;
    }
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, pieces), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t k = r.begin(); k != r.end(); ++k) body(k);
    });
}

}  // namespace

// DARKROOM_POISON_PLANES=1 turns poisoning on for a whole process (the test
// suite sets it).
PlanePool::PlanePool() {
    const char* env = std::getenv("DARKROOM_POISON_PLANES");
    poison_ = env && *env && *env != '0';
}

PlanePool& PlanePool::shared() {
    // Never destroyed: planes may be released during static destruction.
    static PlanePool* pool = new PlanePool();
    return *pool;
}

std::shared_ptr<HostPlane> PlanePool::acquire(std::size_t pixels, Fill how) {
    const std::size_t bytes = roundedBytes(pixels);
    if (bytes >= kHugePage) return acquireMapped(pixels, how);
    void* storage = nullptr;
    bool poison = false;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        poison = poison_;
        auto it = idle_.find(bytes);
        if (it != idle_.end()) {
            storage = it->second;
            idle_.erase(it);
            idleBytes_ -= bytes;
        }
    }
    if (!storage) storage = allocatePlane(bytes);
    if (how == Fill::Zero)
        fill(storage, bytes, 0u);
    else if (poison)
        fill(storage, bytes, kPoison);
    return std::make_shared<HostPlane>(storage, pixels, [this, bytes](void* s) { release(s, bytes); });
}

// Planes of a huge page or more come from the SDK's mappings
// (newHostPlane), the memory the readers' planes come from too: one idle
// store for both, so a pass's output reuses what a reader's plane gave
// back. With a store each, a one-shot `darkroom run` of the demo left the
// readers' released planes idle while its passes took fresh pages, whose
// clearing by the kernel was 15 % of the run's CPU.
std::shared_ptr<HostPlane> PlanePool::acquireMapped(std::size_t pixels, Fill how) {
    std::shared_ptr<HostPlane> plane = newHostPlane(pixels, false);
    bool poison = false;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        poison = poison_;
    }
    if (how == Fill::Zero)
        fill(plane->writableData(), pixels * 4, 0u);
    else if (poison)
        fill(plane->writableData(), pixels * 4, kPoison);
    return plane;
}

void PlanePool::release(void* storage, std::size_t bytes) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (idleBytes_ + bytes <= idleCapacity_) {
            idle_.emplace(bytes, storage);
            idleBytes_ += bytes;
            return;
        }
    }
    std::free(storage);
}

void PlanePool::setPoison(bool on) {
    std::lock_guard<std::mutex> lock(mutex_);
    poison_ = on;
}

}  // namespace darkroom
