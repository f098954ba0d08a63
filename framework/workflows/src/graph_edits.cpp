#include "graph_edits.h"

#include <algorithm>

namespace darkroom::workflows::batch {

GraphEdits::~GraphEdits() {
    // Parameters first (an input given a path in place of its edge loses it),
    // then the edges; the values were the graph's, so nothing is refused.
    try {
        for (auto it = parameters_.rbegin(); it != parameters_.rend(); ++it) {
            if (it->value) g_.setParameter(it->node, it->port, *it->value);
            else g_.clearParameter(it->node, it->port);
        }
        for (const Edge& e : edges_) g_.connect(e.from, e.to);
    } catch (...) {
        // A graph the batch cannot put back is left as the batch made it.
    }
}

void GraphEdits::set(const std::string& node, const std::string& port, Value value) {
    const bool known = std::any_of(parameters_.begin(), parameters_.end(),
                                   [&](const Saved& s) { return s.node == node && s.port == port; });
    if (!known) {
        const Value* before = g_.node(node)->parameter(port);
        parameters_.push_back({node, port, before ? std::optional<Value>(*before) : std::nullopt});
    }
    g_.setParameter(node, port, std::move(value));
}

void GraphEdits::disconnect(const Edge& e) {
    g_.disconnect(e.from, e.to);
    edges_.push_back(e);
}

}  // namespace darkroom::workflows::batch
