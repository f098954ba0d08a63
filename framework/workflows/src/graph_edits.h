#pragma once
// The batch's edits of the caller's graph (an entry's parameters, staging
// paths, an edge replaced after the last entry), undone when it goes out of
// scope: a long-lived front end (the editor, a notebook) keeps the pipeline
// it had, and only the evaluator's cache remembers the batch.
#include <darkroom/core/graph.h>

#include <optional>
#include <string>
#include <vector>

namespace darkroom::workflows::batch {

class GraphEdits {
public:
    explicit GraphEdits(Graph& g) : g_(g) {}
    ~GraphEdits();
    GraphEdits(const GraphEdits&) = delete;
    GraphEdits& operator=(const GraphEdits&) = delete;
    const Graph& graph() const { return g_; }
    void set(const std::string& node, const std::string& port, Value value);
    void disconnect(const Edge& e);

private:
    struct Saved {
        std::string node, port;
        std::optional<Value> value;  // unset: the port's default
    };
    Graph& g_;
    std::vector<Saved> parameters_;
    std::vector<Edge> edges_;
};

}  // namespace darkroom::workflows::batch
