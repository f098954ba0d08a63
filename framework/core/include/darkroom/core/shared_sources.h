#pragma once
// Results of source nodes (nodes that read no image: CinemaReader,
// ImageReader, Capture, ...) shared between evaluators. The editor runs two
// evaluators on two threads, one at full resolution and one for previews,
// over copies of one graph: without sharing, each reads the same databases
// for itself (at 2048 x 2048, three databases take over a second, and the
// first drag after opening waited for them).
//
// An entry is keyed as the evaluator keys a node (type, where paths
// resolve, every value input) and holds the stamps of the files it read, so
// it is used only while every file is unchanged. Images are held weakly: an
// entry lives as long as some evaluator's cache keeps its planes, so sharing
// adds no memory and every evaluator's cache cap still bounds what is held.
// Thread-safe.
#include <darkroom/export.h>

#include <cstddef>
#include <cstdint>
#include <memory>

namespace darkroom {

class DARKROOM_API SharedSources {
public:
    SharedSources();
    ~SharedSources();
    SharedSources(const SharedSources&) = delete;
    SharedSources& operator=(const SharedSources&) = delete;

    // Entries whose images are still held somewhere (tests, statistics).
    std::size_t liveEntries() const;
    // Times an evaluator took a source's outputs from here instead of running it.
    std::uint64_t hits() const;

    struct Impl;  // the evaluator's records (private to the core library)

private:
    friend class Evaluator;
    std::unique_ptr<Impl> impl_;
};

}  // namespace darkroom
