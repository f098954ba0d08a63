#include "host_context.h"
#include "node_runner.h"
#include "plane_pool.h"

#include <darkroom/error.h>
#include <darkroom/capture_backend.h>
#include <darkroom/core/run_filter.h>

#include <tbb/task_arena.h>

namespace darkroom {

namespace {

// A context that owns its thread arena, so parallelFor honours `threads` even
// when the caller is not inside an evaluator.
class StandaloneContext final : public Context {
public:
    StandaloneContext(const FilterRunOptions& o, std::string name)
        : arena_(o.threads > 0 ? o.threads : tbb::task_arena::automatic), inner_([&] {
              HostContext::Setup s;
              s.nodeName = std::move(name);
              s.inputBase = o.inputBase;
              s.outputDir = o.outputDir;
              s.registry = o.registry;
              s.onWarning = [this](const std::string& m) { warnings_.push_back(m); };
              return s;
          }()) {}

    const std::string& nodeName() const override { return inner_.nodeName(); }
    BufferPtr image(std::string_view) const override { return nullptr; }
    std::vector<BufferPtr> images(std::string_view) const override { return {}; }
    const Value& value(std::string_view port) const override {
        throw Error("a standalone context has no input '" + std::string(port) + "'");
    }
    std::string resolveInputPath(std::string_view p) const override { return inner_.resolveInputPath(p); }
    std::string resolveOutputPath(std::string_view p) const override { return inner_.resolveOutputPath(p); }
    void readsFile(const std::string&) override {}
    std::shared_ptr<WritableBuffer> allocate(int w, int h, std::vector<ChannelDesc> c, Fill fill) override {
        return inner_.allocate(w, h, std::move(c), fill);
    }
    std::shared_ptr<WritableBuffer> derive(const BufferPtr& in, std::vector<ChannelDesc> fresh, Fill fill,
                                           std::vector<std::string> drop) override {
        return inner_.derive(in, std::move(fresh), fill, std::move(drop));
    }
    void setOutput(std::string_view port, Value v) override { inner_.setOutput(port, std::move(v)); }
    std::unique_ptr<CaptureBackend> createBackend(std::string_view type) const override {
        return inner_.createBackend(type);
    }
    void progress(double) override {}
    bool cancelled() const override { return false; }
    void warn(std::string_view m) override { warnings_.emplace_back(m); }
    void parallelFor(int begin, int end, int grain, const std::function<void(int, int)>& body) override {
        arena_.execute([&] { inner_.parallelFor(begin, end, grain, body); });
    }

private:
    tbb::task_arena arena_;
    HostContext inner_;
    std::vector<std::string> warnings_;
};

}  // namespace

std::unique_ptr<Context> makeStandaloneContext(const FilterRunOptions& options, std::string nodeName) {
    return std::make_unique<StandaloneContext>(options, std::move(nodeName));
}

FilterRunResult runFilter(Filter& filter, const std::map<std::string, std::vector<Value>>& inputs,
                          const FilterRunOptions& options) {
    // The production path: the same node runner the evaluator uses.
    const PortList ports = filter.ports();
    FilterRunResult result;
    NodeCall call;
    call.filter = &filter;
    call.ports = &ports;
    call.name = options.nodeName;
    call.type = options.nodeType;
    call.inputs = inputs;
    call.inputBase = options.inputBase;
    call.outputDir = options.outputDir;
    call.registry = options.registry;
    call.onWarning = [&](const std::string& m) { result.warnings.push_back(m); };
    if (options.poison) PlanePool::shared().setPoison(true);
    tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
    NodeResult r;
    const SequenceInfo one{1};
    filter.beginSequence(one);
    try {
        arena.execute([&] { r = runNode(call); });
    } catch (...) {
        try {
            filter.endSequence(one, false);
        } catch (...) {
            // The execute's failure is the one reported.
        }
        throw;
    }
    filter.endSequence(one, true);
    result.outputs = std::move(r.outputs);
    return result;
}

}  // namespace darkroom
