#pragma once
// The one way a node runs, whether the evaluator, runFilter or a test calls
// it: required channels checked, the filter executed behind the error
// boundary (an exception becomes an error naming the node once), outputs
// checked, planes sealed, and a record of what the filter read and how each
// output relates to its inputs — what the evaluator's cache is keyed on.
#include "upstream_input.h"

#include <darkroom/filter.h>
#include <darkroom/core/registry.h>

#include <atomic>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace darkroom {

// A file's identity for caching: modification time and size.
struct FileStamp {
    std::string path;
    bool exists = false;
    std::int64_t mtimeNs = 0;
    std::uintmax_t size = 0;
    bool operator==(const FileStamp&) const = default;
};
FileStamp stampOf(const std::string& path);

// What a filter read of one input buffer (port, index in edge order).
struct InputRead {
    std::string port;
    int index = 0;
    int width = 0, height = 0;
    bool channelList = false;
    std::uint64_t channelListHash = 0;
    bool metadata = false;
    std::uint64_t metadataHash = 0;
    struct PlaneRead {
        std::string name;
        std::uint64_t id = 0;  // 0: the channel was absent
        int type = -1;
    };
    std::vector<PlaneRead> planes;
};

// Changes a derived output made to its input's metadata.
struct MetadataDelta {
    bool cameraChanged = false;
    std::optional<Camera> camera;
    std::map<std::string, std::string> set;
    std::vector<std::string> erased;
    BufferMetadata applyTo(const BufferMetadata& m) const;
};

// How an output came about.
struct OutputOrigin {
    enum class Kind { Value, Fresh, Forward, Derived };
    Kind kind = Kind::Value;
    std::string port;  // Forward, Derived: the input it came from
    int index = 0;
    std::vector<ChannelDesc> fresh;  // Derived: derive()'s arguments
    std::vector<std::string> drop;
    MetadataDelta delta;
};

struct NodeCall {
    Filter* filter = nullptr;
    const PortList* ports = nullptr;
    std::string name, type;
    // Image inputs: every connected buffer in edge order; value inputs: one value.
    std::map<std::string, std::vector<Value>> inputs;
    std::string inputBase, outputDir;
    const Registry* registry = nullptr;
    const std::atomic<bool>* cancel = nullptr;
    std::function<void(double)> onProgress;
    std::function<void(const std::string&)> onWarning;
    // What the nodes upstream read: an output over one of them is refused
    // (HostContext::Setup::upstreamInputs).
    std::function<std::vector<UpstreamInput>()> upstreamInputs;
};

struct NodeResult {
    std::map<std::string, Value> outputs;
    std::map<std::string, OutputOrigin> origins;
    std::vector<InputRead> reads;
    std::vector<FileStamp> files;  // readsFile() and every Path input
    std::vector<std::string> inputs;  // HostContext::inputsRead(): what downstream outputs must spare
    std::size_t bytesAllocated = 0;
    double seconds = 0;
};

// "node 'name' (Type)": how every message about a node begins.
std::string nodeLabel(const std::string& name, const std::string& type);

// Throws darkroom::Error beginning with nodeLabel(), or Cancelled.
NodeResult runNode(const NodeCall& call);

// What `read` saw in `buffer` is still what `buffer` holds; otherwise `why`
// (when given) says what differs.
bool stillMatches(const InputRead& read, const Buffer& buffer, std::string* why = nullptr);

// The output a derived one would be with `input` as its input: the recorded
// fresh planes of `previous` around the planes of `input`.
BufferPtr rederive(const OutputOrigin& origin, const Buffer& previous, const Buffer& input);

}  // namespace darkroom
