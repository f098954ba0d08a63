#pragma once
#include <darkroom/error.h>
#include <darkroom/export.h>
#include <darkroom/framework/graph.h>

#include <atomic>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace darkroom {

struct EvaluatorOptions {
    int threads = 0;          // 0 = all hardware threads
    std::string inputBase;    // relative input paths resolve here (the pipeline's folder)
    std::string outputDir;    // relative output paths resolve here (--output), else inputBase
    // Overall progress in [0, 1] over the nodes that must run, and the node running now.
    std::function<void(double, const std::string&)> onProgress;
    std::function<void(const Diagnostic&)> onWarning;
};

// Raised when the graph fails validation before anything runs.
class DARKROOM_API GraphError : public Error {
public:
    explicit GraphError(Diagnostics d);
    ~GraphError() override;
    const Diagnostics& diagnostics() const { return diagnostics_; }

private:
    Diagnostics diagnostics_;
};

// Pull, lazy, cached evaluation. Asking for an output runs only the nodes it
// depends on, and only those whose own version or upstream changed since
// they last ran. Nodes at the same depth run concurrently; filters split
// their work with Context::parallelFor inside an arena of `threads` threads.
//
// The graph is passed per call, so a UI can edit its graph while a copy is
// being evaluated; cache keys are node versions, unique per process.
class DARKROOM_API Evaluator {
public:
    explicit Evaluator(EvaluatorOptions options = {});
    ~Evaluator();

    void setOptions(EvaluatorOptions options);
    const EvaluatorOptions& options() const { return options_; }

    // Value of one output port. Throws GraphError before running anything if
    // the needed part of the graph is invalid, darkroom::Error naming the node
    // if a filter fails, Cancelled if cancel() was called.
    Value evaluate(const Graph& graph, const std::string& node, const std::string& port);
    BufferPtr evaluateImage(const Graph& graph, const std::string& node, const std::string& port);
    // Executes the given nodes (default: every sink) and what they depend on.
    void run(const Graph& graph, std::vector<std::string> nodes = {});

    // Thread-safe; the running evaluation stops at the next check and throws
    // Cancelled. Cleared at the start of the next evaluate/run.
    void cancel() { cancelled_ = true; }
    bool isCancelled() const { return cancelled_; }

    // How many times a node has executed (for tests and the editor's stats).
    std::uint64_t executions(const std::string& node) const;
    // Seconds the last execution of a node took.
    double lastSeconds(const std::string& node) const;
    void clearCache();

private:
    struct NodeState;
    std::uint64_t cacheKey(const Graph& g, const std::string& node,
                           std::map<std::string, std::uint64_t>& memo) const;
    void ensure(const Graph& g, const std::vector<std::string>& targets);
    void execute(const Graph& g, const Node& n, std::uint64_t key, NodeState& state);

    EvaluatorOptions options_;
    std::atomic<bool> cancelled_{false};
    mutable std::mutex mutex_;
    std::map<std::string, std::unique_ptr<NodeState>> states_;
    struct Progress;
    Progress* progress_ = nullptr;
};

}  // namespace darkroom
