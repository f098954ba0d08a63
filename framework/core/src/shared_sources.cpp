#include "shared_sources_impl.h"

#include <algorithm>

namespace darkroom {

namespace {

// The entry's values, images locked; nullopt when one is gone.
std::optional<std::map<std::string, Value>> lockOutputs(const SharedSources::Impl::Entry& e) {
    std::map<std::string, Value> out;
    for (const auto& [port, held] : e.outputs) {
        if (const auto* v = std::get_if<Value>(&held)) {
            out.emplace(port, *v);
            continue;
        }
        BufferPtr image = std::get<std::weak_ptr<const Buffer>>(held).lock();
        if (!image) return std::nullopt;
        out.emplace(port, Value(std::move(image)));
    }
    return out;
}

bool filesUnchanged(const std::vector<FileStamp>& files) {
    for (const auto& f : files)
        if (!(stampOf(f.path) == f)) return false;
    return true;
}

}  // namespace

SharedSources::SharedSources() : impl_(std::make_unique<Impl>()) {}
SharedSources::~SharedSources() = default;

std::size_t SharedSources::liveEntries() const {
    std::lock_guard<std::mutex> lock(impl_->mutex);
    std::size_t n = 0;
    for (const auto& [key, e] : impl_->entries) n += lockOutputs(e).has_value();
    return n;
}

std::uint64_t SharedSources::hits() const {
    std::lock_guard<std::mutex> lock(impl_->mutex);
    return impl_->hits;
}

std::optional<SourceResult> SharedSources::Impl::find(std::uint64_t key) {
    std::lock_guard<std::mutex> lock(mutex);
    const auto it = entries.find(key);
    if (it == entries.end()) return std::nullopt;
    std::optional<std::map<std::string, Value>> outputs = lockOutputs(it->second);
    // Stamps are taken under the lock: a file rewritten since the entry was
    // stored makes it stale for every evaluator at once.
    if (!outputs || !filesUnchanged(it->second.files)) {
        entries.erase(it);
        return std::nullopt;
    }
    ++hits;
    return SourceResult{std::move(*outputs), it->second.origins, it->second.files, it->second.inputs};
}

bool SharedSources::Impl::holds(std::uint64_t key) {
    std::lock_guard<std::mutex> lock(mutex);
    const auto it = entries.find(key);
    return it != entries.end() && lockOutputs(it->second) && filesUnchanged(it->second.files);
}

void SharedSources::Impl::store(std::uint64_t key, const SourceResult& result) {
    Entry e;
    for (const auto& [port, v] : result.outputs) {
        if (const auto* b = std::get_if<BufferPtr>(&v.storage()); b && *b)
            e.outputs.emplace(port, std::weak_ptr<const Buffer>(*b));
        else
            e.outputs.emplace(port, v);
    }
    // Only what holds an image expires with the caches; a source of values
    // alone is cheap to run again.
    const bool anyImage = std::any_of(e.outputs.begin(), e.outputs.end(),
                                      [](const auto& o) { return o.second.index() == 1; });
    if (!anyImage) return;
    e.origins = result.origins;
    e.files = result.files;
    e.inputs = result.inputs;
    std::lock_guard<std::mutex> lock(mutex);
    // Entries whose images every evaluator has let go of are dropped here,
    // so the map holds no more than the caches do.
    for (auto it = entries.begin(); it != entries.end();)
        it = lockOutputs(it->second) ? std::next(it) : entries.erase(it);
    entries[key] = std::move(e);
}

}  // namespace darkroom
