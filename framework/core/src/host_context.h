#pragma once
// The Context implementation shared by every way of running a node (the
// evaluator, runFilter, standalone contexts for capture backends).
//
// Image inputs reach the filter wrapped in TrackedBuffer, so the host learns
// what the filter read; planes come from the PlanePool; derive() shares the
// input's planes and is remembered, so the evaluator can later re-assemble
// the output around new input planes without running the filter.
#include "tracked_buffer.h"
#include "upstream_input.h"

#include <darkroom/context.h>
#include <darkroom/port.h>

#include <atomic>
#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace darkroom {

class Registry;

class HostContext final : public Context {
public:
    struct Setup {
        std::string nodeName;
        const PortList* ports = nullptr;
        // Image inputs: every connected buffer in edge order; value inputs: one value.
        std::map<std::string, std::vector<Value>> inputs;
        std::string inputBase;
        std::string outputDir;
        const Registry* registry = nullptr;
        const std::atomic<bool>* cancelFlag = nullptr;
        std::function<void(double)> onProgress;
        std::function<void(const std::string&)> onWarning;
        // What the nodes upstream of this one read (files and input paths
        // they resolved), so that an output overwriting them is refused.
        // Asked for only when the node resolves an output path: a walk of
        // everything upstream for every node would cost a long chain N².
        std::function<std::vector<UpstreamInput>()> upstreamInputs;
    };

    // What derive() was asked for, per buffer it made.
    struct Derivation {
        std::string port;
        int index = 0;
        std::vector<ChannelDesc> fresh;
        std::vector<std::string> drop;
    };

    explicit HostContext(Setup setup);

    const std::string& nodeName() const override { return s_.nodeName; }
    BufferPtr image(std::string_view port) const override;
    std::vector<BufferPtr> images(std::string_view port) const override;
    const Value& value(std::string_view port) const override;
    std::string resolveInputPath(std::string_view path) const override;
    std::string resolveOutputPath(std::string_view path) const override;
    void readsFile(const std::string& path) override;
    std::shared_ptr<WritableBuffer> allocate(int width, int height, std::vector<ChannelDesc> channels,
                                             Fill fill) override;
    std::shared_ptr<WritableBuffer> derive(const BufferPtr& in, std::vector<ChannelDesc> fresh, Fill fill,
                                           std::vector<std::string> drop) override;
    void setOutput(std::string_view port, Value value) override;
    std::unique_ptr<CaptureBackend> createBackend(std::string_view type) const override;
    void progress(double fraction) override;
    bool cancelled() const override;
    void warn(std::string_view message) override;
    void parallelFor(int begin, int end, int grain, const std::function<void(int, int)>& body) override;

    // --- for the node runner ---
    std::map<std::string, Value>& outputs() { return outputs_; }
    // Read logs per (port, index) of the image inputs.
    const std::map<std::pair<std::string, int>, std::unique_ptr<ReadLog>>& readLogs() const { return logs_; }
    const Derivation* derivation(const Buffer* b) const;
    const std::vector<std::string>& filesRead() const { return files_; }
    // The paths the filter itself resolved as inputs and the files it said
    // it read, absolute: what a downstream output must not overwrite.
    std::vector<std::string> inputsRead() const;
    std::size_t bytesAllocated() const { return bytes_.load(); }
    // Whether the node has run past limit(Limit::NodeMilliseconds) since this
    // context was made; cancelled() turns true then too, so the node stops
    // at its next check (each row block of parallelFor).
    bool overTime() const;
    const Setup& setup() const { return s_; }

private:
    const PortSpec* inputPort(std::string_view port) const;
    std::shared_ptr<HostPlane> newPlane(std::size_t pixels, Fill fill);

    Setup s_;
    // Tracked views of the image inputs, by port, in edge order.
    std::map<std::string, std::vector<BufferPtr>, std::less<>> tracked_;
    std::map<std::pair<std::string, int>, std::unique_ptr<ReadLog>> logs_;
    std::map<std::string, Value> outputs_;
    mutable std::mutex mutex_;  // derivations_, files_ (filters may call from worker threads)
    std::map<const Buffer*, Derivation> derivations_;
    std::vector<std::string> files_;
    mutable std::vector<std::string> inputPaths_;  // resolveInputPath() results
    std::atomic<std::size_t> bytes_{0};
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
    std::uint64_t timeLimitMs_ = 0;  // 0: none
};

}  // namespace darkroom
