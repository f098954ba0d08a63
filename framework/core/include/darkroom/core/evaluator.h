#pragma once
#include <darkroom/error.h>
#include <darkroom/export.h>
#include <darkroom/filter.h>
#include <darkroom/core/graph.h>
#include <darkroom/core/shared_sources.h>

#include <atomic>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <set>
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
    // Cap on the memory of cached outputs (distinct planes counted once);
    // beyond it the least recently used nodes' outputs are dropped after an
    // evaluation. 0 = no cap.
    std::size_t cacheBytes = std::size_t(2) << 30;
    // false: an output is dropped as soon as no node of the current
    // evaluation needs it any more, so a one-shot run holds only what is in
    // flight; the next evaluation recomputes everything.
    bool retainIntermediate = true;
    // Source results shared with other evaluators (shared_sources.h): a
    // node that reads no image takes another evaluator's outputs for the
    // same key and unchanged files instead of running. Null: not shared.
    std::shared_ptr<SharedSources> sharedSources;
};

// How one node fared in the last evaluation.
struct NodeProfile {
    enum class Status {
        Ran,          // executed
        Reassembled,  // not executed: what it read is unchanged; its output was re-made around new input planes
        Cached,       // not executed, output unchanged
    };
    std::string node;
    std::string type;
    Status status = Status::Cached;
    double seconds = 0;              // execution time (0 when not executed)
    std::size_t bytesAllocated = 0;  // new planes it allocated
    std::string reason;              // why it ran: "no cached result", "value inputs changed", ...
};
DARKROOM_API const char* toString(NodeProfile::Status s);

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
// depends on, and only those whose result can have changed.
//
// Caching is channel-granular. A node is keyed by its type, its value inputs
// (a Path input also by the file's modification time and size, as is every
// file the filter named with Context::readsFile), and by exactly what it read
// of its image inputs: the identity of each plane it asked for, the channel
// list and the metadata if it looked at them, and the size. Planes are
// identified by Plane::id; a node that recomputes a plane bit-identical to its
// previous one keeps the previous plane, so downstream keys stay valid. When
// a node's key is unchanged but planes it only passed on changed (derive(),
// or an input forwarded as is), its output is re-assembled from the cached
// planes and the new inputs without executing it.
//
// Nodes at the same depth run concurrently; filters split their work with
// Context::parallelFor inside an arena of `threads` threads. The graph is
// passed per call, so a UI can edit its graph while a copy is evaluated.
class DARKROOM_API Evaluator {
public:
    explicit Evaluator(EvaluatorOptions options = {});
    ~Evaluator();

    void setOptions(EvaluatorOptions options);
    const EvaluatorOptions& options() const { return options_; }

    // Value of one output port. Throws GraphError before running anything if
    // the needed part of the graph is invalid, darkroom::Error naming the node
    // if a filter fails, Cancelled if cancel() was called.
    //
    // `cancel`, when given, is this evaluation's own flag: setting it (from
    // any thread, before or during the run) stops it at the next check —
    // within one row block of a parallelFor — and it throws Cancelled. A UI
    // makes one flag per job, so a cancel that arrives as a run starts is
    // never lost.
    Value evaluate(const Graph& graph, const std::string& node, const std::string& port,
                   const std::atomic<bool>* cancel = nullptr);
    BufferPtr evaluateImage(const Graph& graph, const std::string& node, const std::string& port,
                            const std::atomic<bool>* cancel = nullptr);
    // Executes the given nodes (default: every sink) and what they depend on.
    void run(const Graph& graph, std::vector<std::string> nodes = {}, const std::atomic<bool>* cancel = nullptr);

    // Thread-safe; cancels the evaluation in progress (one started without
    // its own flag), or, if none is running, the next one to start.
    void cancel() { cancelled_ = true; }
    bool isCancelled() const { return cancelled_; }

    // How many times a node has executed (for tests and the editor's stats).
    std::uint64_t executions(const std::string& node) const;
    // Seconds the last execution of a node took.
    double lastSeconds(const std::string& node) const;
    // Every node the last evaluate/run needed, in the order they finished.
    std::vector<NodeProfile> lastProfile() const;
    // The nodes an evaluation of `targets` would execute now, without running
    // anything: those with no cached result, a changed value input, a changed
    // file, or a node upstream that would execute (counted as executing,
    // though it may end in a cached result when it recomputes the same
    // planes). What a UI asks instead of modelling the cache itself.
    std::set<std::string> wouldRun(const Graph& graph, const std::vector<std::string>& targets) const;
    // Memory held by cached outputs (distinct planes counted once).
    std::size_t cachedBytes() const;
    // Drops every cached result; a sequence in progress is ended first for
    // the filters that began it (as not completed).
    void clearCache();

    // The sequence bracket (filter.h). Between beginSequence and
    // endSequence, evaluations form one sequence: each filter gets
    // beginSequence before its first execute() in it, and what it holds
    // between executes (a CinemaWriter its open, locked database) stays
    // held. endSequence ends every filter that began — all of them, even
    // when one fails — and then throws an Error naming the first node whose
    // endSequence failed. An evaluation outside a sequence is a sequence of
    // its own, ended as it returns or throws, so a filter holds nothing
    // between evaluations. Sequences do not nest; one evaluation at a time.
    void beginSequence(SequenceInfo info = {});
    void endSequence(bool completed = true);
    bool inSequence() const;

private:
    struct NodeState;
    void ensure(const Graph& g, const std::vector<std::string>& targets, const std::atomic<bool>* cancel);
    void evaluateWaves(const Graph& g, const std::vector<std::string>& targets, const std::atomic<bool>* cancel);
    void beginSequenceOf(const Node& n, NodeState& st);
    void process(const Graph& g, const Node& n, NodeState& st, const std::atomic<bool>& cancel);
    NodeProfile execute(const Graph& g, const Node& n, NodeState& st, std::map<std::string, std::vector<Value>> inputs,
                        std::uint64_t key, const std::atomic<bool>& cancel);
    bool adoptShared(std::uint64_t key, NodeState& st);
    void publishShared(std::uint64_t key, const NodeState& st);
    void enforceCap(const std::set<std::string>& targets);
    std::size_t cachedBytesLocked() const;

    EvaluatorOptions options_;
    std::atomic<bool> cancelled_{false};
    mutable std::mutex mutex_;
    std::map<std::string, std::unique_ptr<NodeState>> states_;
    std::vector<NodeProfile> profile_;
    std::uint64_t clock_ = 0;  // evaluation counter, for least-recently-used eviction
    struct Progress;
    Progress* progress_ = nullptr;
    bool sequenceOpen_ = false;
    SequenceInfo sequence_;
};

// A sequence of an evaluator for a scope: begun on construction, ended on
// destruction as not completed (never throwing) unless end() ended it. The
// batch workflow holds one around the entries a process shades.
class DARKROOM_API EvaluatorSequence {
public:
    explicit EvaluatorSequence(Evaluator& evaluator, SequenceInfo info = {});
    ~EvaluatorSequence();
    EvaluatorSequence(const EvaluatorSequence&) = delete;
    EvaluatorSequence& operator=(const EvaluatorSequence&) = delete;
    // Ends the sequence as completed; throws what Evaluator::endSequence throws.
    void end();

private:
    Evaluator* evaluator_;
};

}  // namespace darkroom
