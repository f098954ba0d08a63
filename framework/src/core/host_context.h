#pragma once
// The Context implementation shared by the evaluator and runFilter().
#include <darkroom/context.h>
#include <darkroom/port.h>

#include <atomic>
#include <functional>
#include <map>
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
    };

    explicit HostContext(Setup setup);

    const std::string& nodeName() const override { return s_.nodeName; }
    BufferPtr image(std::string_view port) const override;
    std::vector<BufferPtr> images(std::string_view port) const override;
    const Value& value(std::string_view port) const override;
    std::string resolveInputPath(std::string_view path) const override;
    std::string resolveOutputPath(std::string_view path) const override;
    std::shared_ptr<WritableBuffer> allocate(int width, int height,
                                             std::vector<ChannelDesc> channels) override;
    void setOutput(std::string_view port, Value value) override;
    std::unique_ptr<CaptureBackend> createBackend(std::string_view type) const override;
    void progress(double fraction) override;
    bool cancelled() const override;
    void warn(std::string_view message) override;
    void parallelFor(int begin, int end, int grain,
                     const std::function<void(int, int)>& body) override;

    std::map<std::string, Value>& outputs() { return outputs_; }

private:
    const PortSpec* inputPort(std::string_view port) const;
    Setup s_;
    std::map<std::string, Value> outputs_;
};

}  // namespace darkroom
