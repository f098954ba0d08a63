#pragma once
#include <darkroom/buffer.h>
#include <darkroom/export.h>
#include <darkroom/value.h>

#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace darkroom {

class CaptureBackend;

// What a filter sees while it executes: its inputs, a way to allocate and
// publish outputs, progress, cancellation and parallel loops. Implemented by
// the host; a filter never constructs one.
class DARKROOM_API Context {
public:
    virtual ~Context();

    virtual const std::string& nodeName() const = 0;

    // --- inputs ---
    // The buffer on an image input; nullptr when an optional input is unconnected.
    virtual BufferPtr image(std::string_view port) const = 0;
    // All buffers on a `multiple` image input, in edge order.
    virtual std::vector<BufferPtr> images(std::string_view port) const = 0;
    // The value of a value input: the connected output, the pipeline's value or the default.
    virtual const Value& value(std::string_view port) const = 0;

    double getFloat(std::string_view port) const { return value(port).asFloat(); }
    std::int64_t getInt(std::string_view port) const { return value(port).asInt(); }
    bool getBool(std::string_view port) const { return value(port).asBool(); }
    const std::string& getString(std::string_view port) const { return value(port).asString(); }
    Color getColor(std::string_view port) const { return value(port).asColor(); }
    Vec3 getVec3(std::string_view port) const { return value(port).asVec3(); }
    // Like image() but throws an Error naming node and port when nothing is connected.
    BufferPtr requireImage(std::string_view port) const;

    // Paths given in a pipeline are relative to the pipeline file; outputs go
    // below the runner's --output directory when one was given.
    virtual std::string resolveInputPath(std::string_view path) const = 0;
    virtual std::string resolveOutputPath(std::string_view path) const = 0;

    // --- outputs ---
    virtual std::shared_ptr<WritableBuffer> allocate(int width, int height,
                                                     std::vector<ChannelDesc> channels) = 0;
    virtual void setOutput(std::string_view port, Value value) = 0;
    void setOutput(std::string_view port, BufferPtr buffer) { setOutput(port, Value(std::move(buffer))); }

    // A capture backend registered under `type` (e.g. "embree"), for nodes that
    // render; throws darkroom::Error listing the registered backends if unknown.
    virtual std::unique_ptr<CaptureBackend> createBackend(std::string_view type) const = 0;

    // --- progress, cancellation, diagnostics ---
    virtual void progress(double fraction) = 0;  // 0..1 within this node
    virtual bool cancelled() const = 0;
    virtual void warn(std::string_view message) = 0;

    // Runs body(begin, end) over [begin, end) split into chunks of at least
    // `grain`, on the host's thread pool (whose size the host controls), and
    // stops early when cancelled. Results must not depend on how it is split.
    virtual void parallelFor(int begin, int end, int grain,
                             const std::function<void(int, int)>& body) = 0;
};

}  // namespace darkroom
