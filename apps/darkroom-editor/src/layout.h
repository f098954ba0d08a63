#pragma once
// Node positions live in the node's extras as `ui: {position: [x, y]}`, the
// one key the editor owns, so they round-trip through the runner's YAML.
#include <darkroom/core/graph.h>

#include <QPointF>

#include <optional>

namespace editor {

std::optional<QPointF> nodePosition(const darkroom::Node& n);
void setNodePosition(darkroom::Graph& g, const std::string& node, QPointF p);
// Places nodes that have no position: column by topological depth (longest
// path from a source), rows in insertion order. Positioned nodes stay.
void autoLayout(darkroom::Graph& g);

}  // namespace editor
