#pragma once
// Everything the editor asks of darkroom::Evaluator, in one place, so a new
// evaluator API is ported here and nowhere else. The editor needs:
// - an image output of a graph copy, with a "stale" question polled while it
//   runs (a newer edit arrived): the run is then cancelled;
// - per node of the evaluated part of the graph: did it run or come from the
//   cache, and how long it took (for the badges and the status bar);
// - a prediction of how long the next evaluation will take (which nodes
//   would run again, times their last duration), to choose the preview size.
//
// Each evaluation gets a cancel flag of its own (Evaluator's per-run flag):
// cancel() and a `stale` answer set it, and a flag set just as the run starts
// is never lost. The profile is the evaluator's own (ran, re-assembled around
// new input planes, or cached).
#include <darkroom/buffer.h>

#include <atomic>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace darkroom {
class Evaluator;
class Graph;
class SharedSources;
}  // namespace darkroom

namespace editor {

struct NodeRun {
    std::string node;
    bool ran = false;          // executed in this evaluation (else its result was cached)
    bool reassembled = false;  // not executed, but its output re-made around new input planes
    double seconds = 0;        // this run's time if ran, else the time of its last run
};

struct FrameProfile {
    std::vector<NodeRun> nodes;  // the evaluated part of the graph, in dependency order
    double seconds = 0;          // wall time of the evaluation
    int ran() const {
        int n = 0;
        for (const auto& r : nodes) n += r.ran;
        return n;
    }
};

class EvaluatorAdapter {
public:
    EvaluatorAdapter();
    // `threads` per filter (0: all) and a cap on cached outputs, for
    // background work (the explorer's pipeline thumbnails).
    EvaluatorAdapter(int threads, std::size_t cacheBytes);
    ~EvaluatorAdapter();
    EvaluatorAdapter(const EvaluatorAdapter&) = delete;
    EvaluatorAdapter& operator=(const EvaluatorAdapter&) = delete;

    // Relative paths in the graph resolve here (the pipeline's folder).
    void setInputBase(const std::string& folder);
    // Source results (readers, captures) shared with other adapters' evaluators,
    // so a database is read once for all of them. Before the first evaluation.
    void shareSources(std::shared_ptr<darkroom::SharedSources> shared);

    // Evaluates node.port. `stale` (may be empty) is asked before the run and
    // whenever the evaluator reports progress; once it says true the run is
    // cancelled and darkroom::Cancelled thrown. Other errors as Evaluator's.
    darkroom::BufferPtr evaluate(const darkroom::Graph& graph, const std::string& node,
                                 const std::string& port, const std::function<bool()>& stale,
                                 FrameProfile* profile);
    // Thread-safe: the running evaluation stops at its next check.
    void cancel();

    // Seconds the nodes that would run again for node.port took last time,
    // as the evaluator says (Evaluator::wouldRun); negative when one of them
    // never ran here (no estimate).
    double predictSeconds(const darkroom::Graph& graph, const std::string& node) const;

    // For each of `nodes` with a channel port (channel_port.h): the channels
    // of the images flowing into it, from this evaluator's cache. Only
    // inputs whose node finished in the last evaluation are looked at, so
    // nothing runs again (a failed node is not retried).
    std::map<std::string, std::vector<std::string>> inputChannels(const darkroom::Graph& graph,
                                                                  const std::vector<std::string>& nodes);

    // Thread-safe counters (tests and statistics).
    std::uint64_t executions(const std::string& node) const;
    double lastSeconds(const std::string& node) const;

private:
    std::shared_ptr<darkroom::Evaluator> evaluator_;
    // The flag of the evaluation in progress (null between evaluations).
    std::shared_ptr<std::atomic<bool>> running_;
    mutable std::mutex mutex_;  // running_
};

// The nodes `node` depends on (itself included), in dependency order.
std::vector<std::string> upstreamOf(const darkroom::Graph& graph, const std::string& node);

// Nodes `node` depends on that wait for input: a required image input is
// not connected (a node just added). Node -> which input. Evaluating would
// only fail validation; the editor says "waiting for input" instead.
std::map<std::string, std::string> waitingForInput(const darkroom::Graph& graph, const std::string& node);

}  // namespace editor
