#pragma once
// What an evaluator stores in and takes from SharedSources (the public
// class is opaque: entries are made of the evaluator's private records).
#include "node_runner.h"

#include <darkroom/core/shared_sources.h>

#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace darkroom {

// A source node's result as its evaluator recorded it.
struct SourceResult {
    std::map<std::string, Value> outputs;
    std::map<std::string, OutputOrigin> origins;
    std::vector<FileStamp> files;
    std::vector<std::string> inputs;
};

struct SharedSources::Impl {
    // Images weakly (see the header), other values as they are.
    using Held = std::variant<Value, std::weak_ptr<const Buffer>>;
    struct Entry {
        std::map<std::string, Held> outputs;
        std::map<std::string, OutputOrigin> origins;
        std::vector<FileStamp> files;
        std::vector<std::string> inputs;
    };

    // The result stored under `key`, if its images are still held and the
    // files it read are unchanged; a stale entry is dropped.
    std::optional<SourceResult> find(std::uint64_t key);
    void store(std::uint64_t key, const SourceResult& result);
    // Whether find(key) would answer, without taking anything.
    bool holds(std::uint64_t key);

    mutable std::mutex mutex;
    std::map<std::uint64_t, Entry> entries;
    std::uint64_t hits = 0;
};

}  // namespace darkroom
