#include "node_runner.h"

#include "hashing.h"
#include "host_context.h"

#include <darkroom/core/graph.h>

#include <darkroom/colormap.h>
#include <darkroom/depth_input.h>
#include <darkroom/error.h>
#include <darkroom/limits.h>
#include <darkroom/channel_text.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <mutex>
#include <stdexcept>

namespace darkroom {

namespace fs = std::filesystem;

namespace {

// Filters of a type that declares itself Unsafe share one lock.
std::mutex& typeLock(const std::string& type) {
    static std::mutex guard;
    static std::map<std::string, std::unique_ptr<std::mutex>> locks;
    std::lock_guard<std::mutex> g(guard);
    auto& m = locks[type];
    if (!m) m = std::make_unique<std::mutex>();
    return *m;
}

MetadataDelta deltaOf(const BufferMetadata& from, const BufferMetadata& to) {
    MetadataDelta d;
    if (!(from.camera == to.camera)) {
        d.cameraChanged = true;
        d.camera = to.camera;
    }
    for (const auto& [k, v] : to.attributes) {
        auto it = from.attributes.find(k);
        if (it == from.attributes.end() || it->second != v) d.set[k] = v;
    }
    for (const auto& [k, v] : from.attributes)
        if (!to.attributes.count(k)) d.erased.push_back(k);
    return d;
}

// Whether `out` is still exactly what derive() made from `in` (the filter may
// have set or removed planes afterwards; then it is treated as fresh).
bool stillDerived(const Buffer& out, const Buffer& in, const HostContext::Derivation& d) {
    std::vector<ChannelDesc> expected;
    auto isFresh = [&](const std::string& n) {
        for (const auto& f : d.fresh)
            if (f.name == n) return true;
        return false;
    };
    for (const auto& c : in.channels()) {
        if (std::find(d.drop.begin(), d.drop.end(), c.name) != d.drop.end()) continue;
        if (isFresh(c.name)) {
            for (const auto& f : d.fresh)
                if (f.name == c.name) expected.push_back(f);
        } else {
            expected.push_back(c);
            if (out.plane(c.name) != in.plane(c.name)) return false;
        }
    }
    for (const auto& f : d.fresh)
        if (!in.hasChannel(f.name)) expected.push_back(f);
    return expected == out.channels() && out.width() == in.width() && out.height() == in.height();
}

}  // namespace

FileStamp stampOf(const std::string& path) {
    FileStamp s;
    s.path = path;
    std::error_code ec;
    const auto status = fs::status(path, ec);
    if (ec || !fs::exists(status)) return s;
    s.exists = true;
    const auto t = fs::last_write_time(path, ec);
    if (!ec) s.mtimeNs = std::chrono::duration_cast<std::chrono::nanoseconds>(t.time_since_epoch()).count();
    if (fs::is_regular_file(status)) s.size = fs::file_size(path, ec);
    return s;
}

BufferMetadata MetadataDelta::applyTo(const BufferMetadata& m) const {
    BufferMetadata out = m;
    if (cameraChanged) out.camera = camera;
    for (const auto& [k, v] : set) out.attributes[k] = v;
    for (const auto& k : erased) out.attributes.erase(k);
    return out;
}

std::string nodeLabel(const std::string& name, const std::string& type) {
    return "node '" + name + "'" + (type.empty() ? std::string() : " (" + type + ")");
}

namespace {

// The inputs as the filter sees them: checked against their ports (required
// channels, value ranges), taken as the port takes them (asPortValue).
std::map<std::string, std::vector<Value>> checkedInputs(const NodeCall& call, const std::string& label) {
    std::map<std::string, std::vector<Value>> out;
    for (const auto& [name, values] : call.inputs) {
        const PortSpec* in = call.ports->input(name);
        if (!in) throw Error(label + ": has no input '" + name + "'", call.name);
        std::vector<Value> vs;
        for (const auto& v : values) {
            Value x;
            try {
                x = asPortValue(in->type, v);
            } catch (const Error& e) {
                throw Error(label + ": input '" + in->name + "': " + e.what(), call.name);
            }
            if (in->type == PortType::Image) {
                const BufferPtr& b = x.asImage();
                if (!b) throw Error(label + ": input '" + in->name + "' received no image", call.name);
                for (const auto& c : in->channels)
                    if (c == "Z" && !b->hasChannel(c))  // name the database that stores no depth
                        throw Error(label + ": input '" + in->name + "': " + missingDepthMessage(*b), call.name);
                    else if (!b->hasChannel(c))
                        throw Error(label + ": input '" + in->name + "' needs channel '" + c + "', but the image has " +
                                    channelListText(*b), call.name);
            } else {
                try {
                    checkValue(*in, x);
                } catch (const Error& e) {
                    throw Error(label + ": " + e.what(), call.name);
                }
            }
            vs.push_back(std::move(x));
        }
        if (!vs.empty()) out[name] = std::move(vs);
    }
    for (const auto& in : call.ports->inputs)
        if (in.type == PortType::Image && !in.optional && !in.multiple && !out.count(in.name))
            throw Error(label + ": input '" + in.name + "' is not connected", call.name);
    return out;
}

// The filter's execute() behind the one error boundary for every call into
// a plugin: whatever it throws becomes an error naming the node once.
void executeGuarded(const NodeCall& call, HostContext& ctx, const std::string& label) {
    auto overTime = [&] {
        char seconds[32];
        std::snprintf(seconds, sizeof seconds, "%g", double(limit(Limit::NodeMilliseconds)) / 1000.0);
        return InputError(label + ": ran past " + limitOption(Limit::NodeMilliseconds) + " " + seconds, call.name);
    };
    try {
        call.filter->execute(ctx);
    } catch (const Cancelled&) {
        if (ctx.overTime()) throw overTime();
        throw;
    } catch (const InputError& e) {
        // Bad input the node found (a missing file, a size over a limit): the
        // runner exits 2 for it, as for a bad pipeline.
        throw InputError(label + ": " + e.what(), call.name);
    } catch (const Error& e) {
        throw Error(label + ": " + e.what(), call.name);
    } catch (const std::bad_alloc&) {
        throw Error(label + ": ran out of memory (" + limitOption(Limit::NodeBytes) +
                    " fails such a node before it takes the machine's memory)",
                    call.name);
    } catch (const std::logic_error& e) {
        // A programming error in the node or a library it calls
        // (std::out_of_range: "map::at"): named as such, not shown bare.
        throw Error(label + ": unexpected failure inside the node (a bug; please report it): " + e.what(),
                    call.name);
    } catch (const std::exception& e) {
        throw Error(label + ": " + e.what(), call.name);
    } catch (...) {
        throw Error(label + ": failed with an unknown exception", call.name);
    }
    if (ctx.overTime()) throw overTime();
    if (ctx.cancelled()) throw Cancelled();
}

BufferPtr inputBuffer(const HostContext& ctx, const std::string& port, int index) {
    auto it = ctx.setup().inputs.find(port);
    if (it == ctx.setup().inputs.end() || index >= int(it->second.size())) return nullptr;
    return it->second[std::size_t(index)].asImage();
}

// How each output came about (the input passed on, derived from an input,
// or fresh), its planes sealed.
void recordOutputs(HostContext& ctx, NodeResult& r) {
    for (auto& [port, value] : ctx.outputs()) {
        OutputOrigin o;
        if (const auto* b = std::get_if<BufferPtr>(&value.storage()); b && *b) {
            BufferPtr buffer = *b;
            std::string inPort;
            int index = 0;
            if (TrackedBuffer::origin(buffer.get(), inPort, index)) {
                o.kind = OutputOrigin::Kind::Forward;  // the input itself, passed on
                o.port = inPort;
                o.index = index;
                buffer = TrackedBuffer::unwrap(buffer);
            } else if (const auto* d = ctx.derivation(buffer.get())) {
                const BufferPtr in = inputBuffer(ctx, d->port, d->index);
                if (in && stillDerived(*buffer, *in, *d)) {
                    o.kind = OutputOrigin::Kind::Derived;
                    o.port = d->port;
                    o.index = d->index;
                    o.fresh = d->fresh;
                    o.drop = d->drop;
                    o.delta = deltaOf(in->metadata(), buffer->metadata());
                } else {
                    o.kind = OutputOrigin::Kind::Fresh;
                }
            } else {
                o.kind = OutputOrigin::Kind::Fresh;
            }
            sealPlanes(*buffer);
            value = Value(std::move(buffer));
        }
        r.origins[port] = std::move(o);
        r.outputs[port] = std::move(value);
    }
}

// What the filter read of each image input: the cache's key.
void recordReads(const HostContext& ctx, NodeResult& r) {
    for (const auto& [key, log] : ctx.readLogs()) {
        const BufferPtr in = inputBuffer(ctx, key.first, key.second);
        if (!in) continue;
        InputRead read;
        read.port = key.first;
        read.index = key.second;
        read.width = in->width();
        read.height = in->height();
        std::lock_guard<std::mutex> lock(log->mutex);
        if ((read.channelList = log->channelList)) read.channelListHash = hashing::hashChannels(in->channels());
        if ((read.metadata = log->metadata)) read.metadataHash = hashing::hashMetadata(in->metadata());
        for (const auto& [name, unused] : log->channels) {
            InputRead::PlaneRead p;
            p.name = name;
            if (const PlanePtr plane = in->plane(name)) {
                p.id = plane->id();
                p.type = int(*in->channelType(name));
            }
            read.planes.push_back(std::move(p));
        }
        r.reads.push_back(std::move(read));
    }
}

// The files the node depends on: those it said it read, every Path (and
// file colour map) input, and what it wrote through an OutputPath, stamped
// after it ran: a written file changed or deleted since makes it run again.
void recordFiles(const HostContext& ctx, const NodeCall& call, NodeResult& r) {
    r.inputs = ctx.inputsRead();
    std::vector<std::string> files = ctx.filesRead();
    for (const auto& in : call.ports->inputs) {
        const bool output = in.type == PortType::OutputPath;
        const bool file = output || in.type == PortType::Path ||
                          (in.type == PortType::ColorMap && !isColorMapPreset(ctx.value(in.name).asString()));
        if (!file) continue;
        const fs::path path(ctx.value(in.name).asString());
        if (path.empty()) continue;
        // Resolved as HostContext's resolveInputPath and resolveOutputPath
        // do, without recording an input as read.
        const std::string& base = output && !call.outputDir.empty() ? call.outputDir : call.inputBase;
        files.push_back(path.is_absolute() || base.empty() ? path.string()
                                                           : (fs::path(base) / path).lexically_normal().string());
    }
    for (const auto& f : files) r.files.push_back(stampOf(f));
}

}  // namespace

NodeResult runNode(const NodeCall& call) {
    const std::string label = nodeLabel(call.name, call.type);
    HostContext::Setup setup;
    setup.nodeName = call.name;
    setup.ports = call.ports;
    setup.inputBase = call.inputBase;
    setup.outputDir = call.outputDir;
    setup.registry = call.registry;
    setup.cancelFlag = call.cancel;
    setup.onProgress = call.onProgress;
    setup.onWarning = call.onWarning;
    setup.upstreamInputs = call.upstreamInputs;
    setup.inputs = checkedInputs(call, label);

    std::unique_lock<std::mutex> typeGuard;
    if (call.filter->threadSafety() == ThreadSafety::Unsafe)
        typeGuard = std::unique_lock<std::mutex>(typeLock(call.type));
    // The node's time limit counts from here, after any wait for the type lock.
    HostContext ctx(std::move(setup));
    const auto t0 = std::chrono::steady_clock::now();
    executeGuarded(call, ctx, label);

    NodeResult r;
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    r.bytesAllocated = ctx.bytesAllocated();
    for (const auto& out : call.ports->outputs)
        if (!ctx.outputs().count(out.name)) throw Error(label + " did not produce its output '" + out.name + "'", call.name);
    recordOutputs(ctx, r);
    recordReads(ctx, r);
    recordFiles(ctx, call, r);
    return r;
}

bool stillMatches(const InputRead& read, const Buffer& b, std::string* why) {
    auto differs = [&](const std::string& what) {
        if (why) *why = "input '" + read.port + "' changed: " + what;
        return false;
    };
    if (b.width() != read.width || b.height() != read.height) return differs("its size");
    if (read.channelList && hashing::hashChannels(b.channels()) != read.channelListHash)
        return differs("its channel list");
    if (read.metadata && hashing::hashMetadata(b.metadata()) != read.metadataHash) return differs("its metadata");
    for (const auto& p : read.planes) {
        const PlanePtr plane = b.plane(p.name);
        const std::uint64_t id = plane ? plane->id() : 0;
        if (id != p.id || (plane && int(*b.channelType(p.name)) != p.type)) return differs("channel " + p.name);
    }
    return true;
}

BufferPtr rederive(const OutputOrigin& o, const Buffer& previous, const Buffer& input) {
    auto out = makeHostBuffer(input.width(), input.height());
    out->metadata() = o.delta.applyTo(input.metadata());
    auto freshDesc = [&](const std::string& name) -> const ChannelDesc* {
        for (const auto& f : o.fresh)
            if (f.name == name) return &f;
        return nullptr;
    };
    for (const auto& c : input.channels()) {
        if (std::find(o.drop.begin(), o.drop.end(), c.name) != o.drop.end()) continue;
        if (const ChannelDesc* f = freshDesc(c.name))
            out->setPlane(*f, previous.plane(f->name));
        else
            out->setPlane(c, input.plane(c.name));
    }
    for (const auto& f : o.fresh)
        if (!input.hasChannel(f.name)) out->setPlane(f, previous.plane(f.name));
    return out;
}

}  // namespace darkroom
