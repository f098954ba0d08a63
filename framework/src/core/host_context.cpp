#include "host_context.h"

#include <darkroom/capture_backend.h>
#include <darkroom/error.h>
#include <darkroom/framework/registry.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <filesystem>

namespace darkroom {

namespace fs = std::filesystem;

HostContext::HostContext(Setup setup) : s_(std::move(setup)) {}

const PortSpec* HostContext::inputPort(std::string_view port) const {
    const PortSpec* p = s_.ports ? s_.ports->input(port) : nullptr;
    if (!p) throw Error("node '" + s_.nodeName + "' asked for input '" + std::string(port) +
                        "', which it does not declare");
    return p;
}

BufferPtr HostContext::image(std::string_view port) const {
    const PortSpec* p = inputPort(port);
    if (p->type != PortType::Image)
        throw Error("node '" + s_.nodeName + "': input '" + p->name + "' is not an image port");
    auto it = s_.inputs.find(p->name);
    if (it == s_.inputs.end() || it->second.empty()) return nullptr;
    return it->second.front().asImage();
}

std::vector<BufferPtr> HostContext::images(std::string_view port) const {
    const PortSpec* p = inputPort(port);
    std::vector<BufferPtr> out;
    auto it = s_.inputs.find(p->name);
    if (it != s_.inputs.end())
        for (const auto& v : it->second) out.push_back(v.asImage());
    return out;
}

const Value& HostContext::value(std::string_view port) const {
    const PortSpec* p = inputPort(port);
    auto it = s_.inputs.find(p->name);
    if (it != s_.inputs.end() && !it->second.empty()) return it->second.front();
    return p->defaultValue;
}

std::string HostContext::resolveInputPath(std::string_view path) const {
    const fs::path p(path);
    if (p.is_absolute() || s_.inputBase.empty()) return p.string();
    return (fs::path(s_.inputBase) / p).lexically_normal().string();
}

std::string HostContext::resolveOutputPath(std::string_view path) const {
    const fs::path p(path);
    const std::string& base = s_.outputDir.empty() ? s_.inputBase : s_.outputDir;
    if (p.is_absolute() || base.empty()) return p.string();
    return (fs::path(base) / p).lexically_normal().string();
}

std::shared_ptr<WritableBuffer> HostContext::allocate(int width, int height,
                                                      std::vector<ChannelDesc> channels) {
    return makeCpuBuffer(width, height, std::move(channels));
}

void HostContext::setOutput(std::string_view port, Value value) {
    const PortSpec* p = s_.ports ? s_.ports->output(port) : nullptr;
    if (s_.ports && !p)
        throw Error("node '" + s_.nodeName + "' set output '" + std::string(port) +
                    "', which it does not declare");
    outputs_[std::string(port)] = std::move(value);
}

std::unique_ptr<CaptureBackend> HostContext::createBackend(std::string_view type) const {
    if (!s_.registry) throw Error("no capture backends are available in this context");
    return s_.registry->createBackend(std::string(type));
}

void HostContext::progress(double fraction) {
    if (s_.onProgress) s_.onProgress(std::clamp(fraction, 0.0, 1.0));
}

bool HostContext::cancelled() const { return s_.cancelFlag && s_.cancelFlag->load(); }

void HostContext::warn(std::string_view message) {
    if (s_.onWarning) s_.onWarning(std::string(message));
}

void HostContext::parallelFor(int begin, int end, int grain,
                              const std::function<void(int, int)>& body) {
    if (end <= begin) return;
    // Runs in whatever TBB arena the caller entered, so the evaluator's thread
    // count applies. Chunks are independent; results must not depend on them.
    tbb::parallel_for(tbb::blocked_range<int>(begin, end, std::max(1, grain)),
                      [&](const tbb::blocked_range<int>& r) {
                          if (cancelled()) return;
                          body(r.begin(), r.end());
                      });
    if (cancelled()) throw Cancelled();
}

}  // namespace darkroom
