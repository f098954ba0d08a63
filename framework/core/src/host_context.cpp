#include "host_context.h"

#include "plane_pool.h"

#include <darkroom/capture_backend.h>
#include <darkroom/error.h>
#include <darkroom/limits.h>
#include <darkroom/core/path_overlap.h>
#include <darkroom/core/registry.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>

namespace darkroom {

namespace fs = std::filesystem;

namespace {

// "1.2 GiB", for messages about --max-node-memory.
std::string humanBytes(std::uint64_t b) {
    const char* units[] = {"bytes", "KiB", "MiB", "GiB", "TiB"};
    double v = double(b);
    int u = 0;
    while (v >= 1024 && u < 4) {
        v /= 1024;
        ++u;
    }
    char buf[48];
    if (u == 0) std::snprintf(buf, sizeof buf, "%llu bytes", static_cast<unsigned long long>(b));
    else std::snprintf(buf, sizeof buf, "%.3g %s", v, units[u]);
    return buf;
}

}  // namespace

HostContext::HostContext(Setup setup) : s_(std::move(setup)), timeLimitMs_(limit(Limit::NodeMilliseconds)) {
    if (!s_.ports) return;
    for (const auto& p : s_.ports->inputs) {
        if (p.type != PortType::Image) continue;
        auto it = s_.inputs.find(p.name);
        if (it == s_.inputs.end()) continue;
        auto& views = tracked_[p.name];
        for (std::size_t i = 0; i < it->second.size(); ++i) {
            const BufferPtr& b = it->second[i].asImage();
            if (!b) {
                views.push_back(nullptr);
                continue;
            }
            auto& log = logs_[{p.name, int(i)}];
            log = std::make_unique<ReadLog>();
            views.push_back(std::make_shared<TrackedBuffer>(b, p.name, int(i), *log));
        }
    }
}

const PortSpec* HostContext::inputPort(std::string_view port) const {
    const PortSpec* p = s_.ports ? s_.ports->input(port) : nullptr;
    if (!p) throw Error("asked for input '" + std::string(port) + "', which the node does not declare");
    return p;
}

BufferPtr HostContext::image(std::string_view port) const {
    const PortSpec* p = inputPort(port);
    if (p->type != PortType::Image) throw Error("input '" + p->name + "' is not an image port");
    auto it = tracked_.find(p->name);
    if (it == tracked_.end() || it->second.empty()) return nullptr;
    return it->second.front();
}

std::vector<BufferPtr> HostContext::images(std::string_view port) const {
    const PortSpec* p = inputPort(port);
    auto it = tracked_.find(p->name);
    return it == tracked_.end() ? std::vector<BufferPtr>{} : it->second;
}

const Value& HostContext::value(std::string_view port) const {
    const PortSpec* p = inputPort(port);
    auto it = s_.inputs.find(p->name);
    if (it != s_.inputs.end() && !it->second.empty()) return it->second.front();
    return p->defaultValue;
}

std::string HostContext::resolveInputPath(std::string_view path) const {
    const fs::path p(path);
    std::string resolved =
        p.is_absolute() || s_.inputBase.empty() ? p.string() : (fs::path(s_.inputBase) / p).lexically_normal().string();
    std::lock_guard<std::mutex> lock(mutex_);
    inputPaths_.push_back(resolved);
    return resolved;
}

std::string HostContext::resolveOutputPath(std::string_view path) const {
    const fs::path p(path);
    const std::string& base = s_.outputDir.empty() ? s_.inputBase : s_.outputDir;
    std::string resolved =
        p.is_absolute() || base.empty() ? p.string() : (fs::path(base) / p).lexically_normal().string();
    // Refused before the node writes anything: an output that is, holds or
    // lies inside what an upstream node read would destroy that input (a
    // CinemaWriter overwriting the database its reader reads).
    for (const UpstreamInput& in : s_.upstreamInputs ? s_.upstreamInputs() : std::vector<UpstreamInput>{})
        if (pathsOverlap(resolved, in.path))
            throw InputError("the output " + resolved + " " + overlapWording(resolved, in.path) + " " + in.path +
                             ", which node '" + in.node + "' upstream reads; writing there would destroy the input. "
                             "Choose an output outside the inputs");
    return resolved;
}

std::vector<std::string> HostContext::inputsRead() const {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<std::string> out;
    const auto add = [&out](const std::vector<std::string>& list) {
        for (const auto& f : list) {
            const std::string a = absoluteNormal(f);
            if (std::find(out.begin(), out.end(), a) == out.end()) out.push_back(a);
        }
    };
    add(inputPaths_);
    add(files_);
    return out;
}

void HostContext::readsFile(const std::string& path) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (std::find(files_.begin(), files_.end(), path) == files_.end()) files_.push_back(path);
}

std::shared_ptr<HostPlane> HostContext::newPlane(std::size_t pixels, Fill fill) {
    const std::size_t total = bytes_ += pixels * 4;
    // Checked before the memory is taken, so a node over the limit fails
    // without first pushing the machine into swap.
    if (const std::uint64_t cap = limit(Limit::NodeBytes); cap != 0 && total > cap)
        throw InputError("allocated " + humanBytes(total) + " of image planes, over " +
                         limitOption(Limit::NodeBytes) + " " + humanBytes(cap));
    return PlanePool::shared().acquire(pixels, fill);
}

std::shared_ptr<WritableBuffer> HostContext::allocate(int width, int height, std::vector<ChannelDesc> channels,
                                                      Fill fill) {
    if (width > 0 && height > 0) checkImagePixels(std::uint64_t(width), std::uint64_t(height), "a new image");
    auto out = makeHostBuffer(width, height);
    for (const auto& c : channels) {
        if (out->hasChannel(c.name)) throw Error("channel '" + c.name + "' appears twice in one image");
        out->setPlane(c, newPlane(out->pixelCount(), fill));
    }
    return out;
}

std::shared_ptr<WritableBuffer> HostContext::derive(const BufferPtr& in, std::vector<ChannelDesc> fresh, Fill fill,
                                                    std::vector<std::string> drop) {
    if (!in) throw Error("derive() was given no image");
    const BufferPtr& base = TrackedBuffer::unwrap(in);
    auto out = makeHostBuffer(base->width(), base->height());
    out->metadata() = base->metadata();
    const std::size_t n = base->pixelCount();
    auto freshDesc = [&](const std::string& name) -> const ChannelDesc* {
        for (const auto& f : fresh)
            if (f.name == name) return &f;
        return nullptr;
    };
    for (std::size_t i = 0; i < fresh.size(); ++i)
        for (std::size_t k = 0; k < i; ++k)
            if (fresh[k].name == fresh[i].name)
                throw Error("derive(): channel '" + fresh[i].name + "' is listed twice");
    // The input's channels in order: shared, replaced in place, or left out.
    for (const auto& c : base->channels()) {
        if (std::find(drop.begin(), drop.end(), c.name) != drop.end()) continue;
        if (const ChannelDesc* f = freshDesc(c.name))
            out->setPlane(*f, newPlane(n, fill));
        else
            out->setPlane(c, base->plane(c.name));
    }
    for (const auto& f : fresh)
        if (!base->hasChannel(f.name)) out->setPlane(f, newPlane(n, fill));

    Derivation d;
    d.fresh = std::move(fresh);
    d.drop = std::move(drop);
    if (TrackedBuffer::origin(in.get(), d.port, d.index)) {
        std::lock_guard<std::mutex> lock(mutex_);
        derivations_[out.get()] = std::move(d);
    }
    return out;
}

const HostContext::Derivation* HostContext::derivation(const Buffer* b) const {
    std::lock_guard<std::mutex> lock(mutex_);
    auto it = derivations_.find(b);
    return it == derivations_.end() ? nullptr : &it->second;
}

void HostContext::setOutput(std::string_view port, Value value) {
    const PortSpec* p = s_.ports ? s_.ports->output(port) : nullptr;
    if (s_.ports && !p) throw Error("set output '" + std::string(port) + "', which the node does not declare");
    outputs_[std::string(port)] = std::move(value);
}

std::unique_ptr<CaptureBackend> HostContext::createBackend(std::string_view type) const {
    if (!s_.registry) throw Error("no capture backends are available in this context");
    return s_.registry->createBackend(std::string(type));
}

void HostContext::progress(double fraction) {
    if (s_.onProgress) s_.onProgress(std::clamp(fraction, 0.0, 1.0));
}

bool HostContext::cancelled() const {
    return (s_.cancelFlag && s_.cancelFlag->load(std::memory_order_relaxed)) || overTime();
}

bool HostContext::overTime() const {
    return timeLimitMs_ != 0 &&
           std::chrono::steady_clock::now() - start_ > std::chrono::milliseconds(std::int64_t(timeLimitMs_));
}

void HostContext::warn(std::string_view message) {
    if (s_.onWarning) s_.onWarning(std::string(message));
}

void HostContext::parallelFor(int begin, int end, int grain, const std::function<void(int, int)>& body) {
    if (end <= begin) return;
    if (cancelled()) throw Cancelled();
    // Runs in whatever TBB arena the caller entered, so the evaluator's thread
    // count applies. Chunks are independent; results must not depend on them.
    // Each chunk checks the flag first, so a cancel stops the work within one
    // row block.
    tbb::parallel_for(tbb::blocked_range<int>(begin, end, std::max(1, grain)),
                      [&](const tbb::blocked_range<int>& r) {
                          if (cancelled()) return;
                          body(r.begin(), r.end());
                      });
    if (cancelled()) throw Cancelled();
}

}  // namespace darkroom
