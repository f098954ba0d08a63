#pragma once
#include <darkroom/context.h>
#include <darkroom/export.h>
#include <darkroom/port.h>

namespace darkroom {

// How the host may call execute() concurrently.
enum class ThreadSafety : std::uint8_t {
    // Only one execute() of this filter type at a time, across all instances
    // (e.g. a library with global state).
    Unsafe,
    // Different instances may execute at the same time; one instance is never
    // entered twice at once. The default.
    InstanceSafe,
};

// A shading pass or any other node. To add one: inherit, declare ports,
// implement execute — nothing else.
class DARKROOM_API Filter {
public:
    virtual ~Filter();

    // Cheap and side-effect free; may be called at any time, many times.
    virtual PortList ports() const = 0;

    // Reads inputs from the context, allocates and publishes every output.
    // Throwing darkroom::Error (or any std::exception) marks this node failed
    // with that message; the host names the node.
    virtual void execute(Context& ctx) = 0;

    virtual ThreadSafety threadSafety() const { return ThreadSafety::InstanceSafe; }
};

}  // namespace darkroom
