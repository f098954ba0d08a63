#pragma once
#include <darkroom/export.h>
#include <darkroom/diagnostics.h>
#include <darkroom/core/graph.h>

#include <optional>
#include <set>
#include <string>

namespace darkroom {

// Current pipeline file format version (the `darkroom:` key).
constexpr int kPipelineFormatVersion = 1;

// Parses a pipeline. Problems are appended to `diagnostics`, each naming
// source:line:column; nodes of unknown type become placeholders (a warning),
// never dropped. The returned graph holds everything that could be read.
DARKROOM_API Graph parsePipeline(const std::string& text, const std::string& sourceName,
                                 const Registry& registry, Diagnostics& diagnostics);
// Reads the file; a missing or unreadable file is an error diagnostic.
DARKROOM_API Graph loadPipeline(const std::string& path, const Registry& registry,
                                Diagnostics& diagnostics);

// The node types a pipeline file names, read without a registry: which
// plugins a run needs (Registry::loadPlugins). None when the file cannot be
// read or parsed, or a node has no plain type: loadPipeline then says why.
DARKROOM_API std::optional<std::set<std::string>> pipelineNodeTypes(const std::string& path);

// Canonical text: saving a loaded canonical file reproduces it byte for byte,
// and loading saved text reproduces the graph exactly.
DARKROOM_API std::string serializePipeline(const Graph& graph);
// Atomic: writes a temporary file beside `path`, then renames it.
DARKROOM_API void savePipeline(const Graph& graph, const std::string& path);

}  // namespace darkroom
