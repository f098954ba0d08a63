#pragma once
#include <darkroom/export.h>
#include <darkroom/diagnostics.h>
#include <darkroom/core/registry.h>
#include <darkroom/port.h>

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

namespace darkroom {

struct Endpoint {
    std::string node;
    std::string port;
    bool operator==(const Endpoint&) const = default;
    std::string str() const { return node + "." + port; }
};

struct Edge {
    Endpoint from;  // an output
    Endpoint to;    // an input
    bool operator==(const Edge&) const = default;
};

// A node: an instance of a registered type with parameter values for its
// unconnected value inputs. A node whose type is not registered is kept as a
// placeholder with its raw parameter text, so nothing is dropped on save.
// A node as the graph holds it. Read-only outside the graph: Graph hands out
// const nodes only, and every change goes through its mutators, which keep
// the name index, the edges and the revision right.
struct Node {
    std::string name;
    std::string type;
    bool placeholder = false;
    // Parameters in the order they were set; only explicitly set ones (the
    // rest take the port default). For placeholders, values are raw text.
    std::vector<std::pair<std::string, Value>> parameters;
    std::map<std::string, std::string> rawParameters;  // placeholders only
    std::vector<std::string> rawParameterOrder;        // placeholders only
    // Editor layout and other per-node keys the host does not interpret,
    // preserved as YAML text.
    std::vector<std::pair<std::string, std::string>> extras;
    // Source position in the pipeline file (1-based; 0 if built in code).
    int line = 0, column = 0;

    const Value* parameter(const std::string& port) const {
        for (const auto& [k, v] : parameters)
            if (k == port) return &v;
        return nullptr;
    }
};

// The node graph: nodes, typed connections, and the checks that must pass
// before anything runs. Every change of what runs (nodes, parameters, edges)
// bumps revision(); the evaluator's cache keys on the values themselves.
class DARKROOM_API Graph {
public:
    explicit Graph(const Registry& registry);

    const Registry& registry() const { return *registry_; }

    // Throws darkroom::Error on duplicate names or (for non-placeholders)
    // an unknown type.
    const Node& addNode(const std::string& name, const std::string& type);
    const Node& addPlaceholder(const std::string& name, const std::string& type);
    // A node of another graph with the same registry, as it is there
    // (parameters, extras, source position); throws like addNode.
    const Node& addCopy(const Node& node);
    void removeNode(const std::string& name);  // also removes its edges
    void renameNode(const std::string& from, const std::string& to);

    // Checks the value against the port (type, range, choices); throws darkroom::Error.
    void setParameter(const std::string& node, const std::string& port, Value value);
    void clearParameter(const std::string& node, const std::string& port);
    // A placeholder's parameter as the pipeline file's YAML text, kept for saving.
    void setRawParameter(const std::string& node, const std::string& port, std::string yamlText);

    // Keys the host does not interpret (editor layout), as YAML text: set or
    // replaced in place, removed when `yamlText` is empty. Not part of what
    // runs, so revision() is unchanged.
    void setExtra(const std::string& node, const std::string& key, const std::string& yamlText);
    void clearExtras(const std::string& node);
    // Where the node was written in the pipeline file, for messages.
    void setSourceLocation(const std::string& node, int line, int column);

    // Checks both ports exist, directions, types, and that the input is free
    // (unless it accepts multiple); throws darkroom::Error with the reason.
    void connect(const Endpoint& from, const Endpoint& to);
    // Whether connect() would succeed; `why` gets the reason if not.
    bool canConnect(const Endpoint& from, const Endpoint& to, std::string* why = nullptr) const;
    void disconnect(const Endpoint& from, const Endpoint& to);
    // Adds an edge without checks (placeholders, loading); validate() reports problems.
    void addEdgeUnchecked(const Edge& e);

    const std::vector<Node>& nodes() const { return nodes_; }
    const Node* node(const std::string& name) const;
    const std::vector<Edge>& edges() const { return edges_; }
    std::vector<Edge> edgesInto(const std::string& node, const std::string& port) const;
    std::vector<Edge> edgesInto(const std::string& node) const;
    // Ports of a node; empty for placeholders.
    const PortList& ports(const Node& n) const;

    // Everything that must hold before running: known types, edges between
    // existing ports of matching types, one edge per single input, required
    // image inputs connected, no cycles. Each diagnostic names the node.
    Diagnostics validate() const;
    // Nodes in dependency order; throws darkroom::Error naming a node on a cycle.
    std::vector<std::string> topologicalOrder() const;
    // Nodes with no outputs, and nodes that write files (an OutputPath
    // input, even with outputs: CinemaWriter says which database it wrote),
    // in insertion order: what a run evaluates.
    std::vector<std::string> sinks() const;
    // The nodes `from` depend on through edges, the existing ones among
    // `from` included; and the nodes that depend on `from`, `from` included.
    // The one walk of the graph's edges for the evaluator, the workflows and
    // the editor; with a stack of its own, since recursion would overflow the
    // thread's stack on a chain of a million nodes.
    std::set<std::string> upstreamOf(const std::vector<std::string>& from) const;
    std::set<std::string> downstreamOf(const std::vector<std::string>& from) const;

    // Bumped by every structural or parameter change anywhere in the graph.
    std::uint64_t revision() const { return revision_; }

private:
    void touch();
    // Rebuilds the lookup tables below after a removal or rename; additions
    // extend them. They are never changed by const methods, so concurrent
    // readers (the evaluator's workers) may share a graph.
    void reindex();
    // The node to change; throws darkroom::Error when there is none.
    Node& mutableNode(const std::string& name);
    bool closesCycle(const std::string& from, const std::string& to) const;
    using EdgeIndex = std::unordered_map<std::string, std::vector<std::size_t>>;
    std::set<std::string> reachable(const std::vector<std::string>& from, const EdgeIndex& index,
                                    bool downstream) const;
    const Registry* registry_;
    std::vector<Node> nodes_;
    std::vector<Edge> edges_;
    // Node position by name, and edge positions by the node they leave and
    // enter, so loading, connecting and validating are linear in the graph
    // (a 5,000-node chain) rather than quadratic or worse.
    std::unordered_map<std::string, std::size_t> nodeIndex_;
    std::unordered_map<std::string, std::vector<std::size_t>> edgesFrom_, edgesTo_;
    std::uint64_t revision_ = 0;
};

// Whether an output of type `from` may feed an input of type `to`.
DARKROOM_API bool compatible(PortType from, PortType to);

// The value as an input of `type` takes it: an integer given to a float port
// widened, a row given as its text ("phi=30, theta=45") parsed — so a
// pipeline, a test or a script may type a row. Throws darkroom::Error on
// bad row text; anything else is returned as is for checkValue to judge.
DARKROOM_API Value asPortValue(PortType type, Value v);

}  // namespace darkroom
