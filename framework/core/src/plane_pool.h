#pragma once
// Where the host's planes come from. Memory given back by released planes is
// kept for the next allocation of the same size (editor edits and --foreach
// entries allocate the same sizes over and over), so a pass pays neither the
// allocator nor the kernel's page faults again; what exceeds the idle
// capacity goes back to the system. Planes of 2 MiB or more share the SDK's
// store of mappings (newHostPlane) with the readers; smaller ones are kept
// here.
#include <darkroom/buffer.h>
#include <darkroom/context.h>

#include <cstddef>
#include <map>
#include <memory>
#include <mutex>

namespace darkroom {

class PlanePool {
public:
    // The pool every host context uses.
    static PlanePool& shared();

    // A writable plane of `pixels` 4-byte values. Fill::Zero zeroes it (in
    // parallel, so fresh pages are first touched by several cores); Fill::None
    // leaves it as it comes, or fills it with kPoison when poisoning is on.
    std::shared_ptr<HostPlane> acquire(std::size_t pixels, Fill fill);

    // Tests turn this on: planes asked for with Fill::None are filled with
    // kPoison, a NaN whose payload no computation produces, so a pass that
    // leaves pixels unwritten is caught.
    void setPoison(bool on);
    static constexpr std::uint32_t kPoison = 0x7fbadbadu;

private:
    PlanePool();
    std::shared_ptr<HostPlane> acquireMapped(std::size_t pixels, Fill fill);
    void release(void* storage, std::size_t bytes);

    mutable std::mutex mutex_;
    std::multimap<std::size_t, void*> idle_;  // bytes -> storage
    std::size_t idleBytes_ = 0;
    std::size_t idleCapacity_ = std::size_t(1) << 30;  // of the small planes kept here
    bool poison_ = false;
};

}  // namespace darkroom
