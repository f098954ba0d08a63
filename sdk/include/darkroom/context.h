#pragma once
#include <darkroom/buffer.h>
#include <darkroom/export.h>
#include <darkroom/port.h>
#include <darkroom/value.h>

#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace darkroom {

class CaptureBackend;

// What a new plane holds before the filter writes it. A pass that writes every
// pixel asks for None and saves a pass over memory; Zero is the safe default.
enum class Fill : std::uint8_t { Zero, None };

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

    // The result of a filter depends on this file (beyond its path inputs,
    // which the host watches already): the host re-runs the node when the
    // file's modification time or size changes. E.g. a database reader names
    // its data.csv and the product it read.
    virtual void readsFile(const std::string& path) = 0;

    // --- outputs ---
    // A new buffer of fresh planes from the host's pool.
    virtual std::shared_ptr<WritableBuffer> allocate(int width, int height, std::vector<ChannelDesc> channels,
                                                     Fill fill = Fill::Zero) = 0;
    // The usual way to produce an image from an image: a buffer like `in` —
    // its size, metadata and every channel shared with it, copying nothing —
    // except the `fresh` channels, which get new writable planes (a name `in`
    // has is replaced in place, a new name is appended), and the `drop`
    // channels, which are left out. A pass that adds AO writes
    //   auto out = ctx.derive(in, {"AO"}, Fill::None);
    // and fills out->requireFloat("AO"). The host knows which planes were
    // passed on, so when only those change upstream it re-assembles the
    // output from the new inputs without running the pass again.
    virtual std::shared_ptr<WritableBuffer> derive(const BufferPtr& in, std::vector<ChannelDesc> fresh,
                                                   Fill fill = Fill::Zero, std::vector<std::string> drop = {}) = 0;
    virtual void setOutput(std::string_view port, Value value) = 0;
    void setOutput(std::string_view port, BufferPtr buffer) { setOutput(port, Value(std::move(buffer))); }

    // --- typed access through port handles (port.h) ---
    BufferPtr get(const ImageIn& p) const { return requireImage(p.name()); }
    BufferPtr get(const OptionalImageIn& p) const { return image(p.name()); }
    std::vector<BufferPtr> get(const ImagesIn& p) const { return images(p.name()); }
    double get(const FloatIn& p) const { return getFloat(p.name()); }
    std::int64_t get(const IntIn& p) const { return getInt(p.name()); }
    bool get(const BoolIn& p) const { return getBool(p.name()); }
    Color get(const ColorIn& p) const { return getColor(p.name()); }
    Vec3 get(const Vec3In& p) const { return getVec3(p.name()); }
    const std::string& get(const StringIn& p) const { return getString(p.name()); }
    const Row& get(const RowIn& p) const { return value(p.name()).asRow(); }
    // A preset name as is; a file path resolved against the pipeline's folder.
    std::string get(const ColorMapIn& p) const;
    // Resolved against the pipeline's folder; empty stays empty.
    std::string get(const PathIn& p) const;
    // Resolved with resolveOutputPath, lexically normal; throws when empty
    // (a writer needs somewhere to write), naming the port.
    std::string get(const OutputPathIn& p) const;
    template <class E>
    E get(const EnumIn<E>& p) const {
        return p.parse(getString(p.name()));
    }
    void set(const ImageOut& p, BufferPtr b) { setOutput(p.name(), Value(std::move(b))); }
    void set(const ValueOut& p, Value v) { setOutput(p.name(), std::move(v)); }

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
