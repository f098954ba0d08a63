#include "layout.h"

#include <QRegularExpression>
#include <QString>

#include <map>

namespace editor {

std::optional<QPointF> nodePosition(const darkroom::Node& n) {
    static const QRegularExpression re(
        R"(position:\s*\[\s*(-?[0-9.eE+-]+)\s*,\s*(-?[0-9.eE+-]+)\s*\])");
    for (const auto& [k, v] : n.extras) {
        if (k != "ui") continue;
        const auto m = re.match(QString::fromStdString(v));
        if (m.hasMatch()) return QPointF(m.captured(1).toDouble(), m.captured(2).toDouble());
    }
    return std::nullopt;
}

void setNodePosition(darkroom::Graph& g, const std::string& node, QPointF p) {
    // Whole numbers keep the file tidy and the text canonical for the loader.
    g.setExtra(node, "ui", "{position: [" + std::to_string(qRound(p.x())) + ", " + std::to_string(qRound(p.y())) + "]}");
}

void autoLayout(darkroom::Graph& g) {
    std::map<std::string, int> depth;
    std::vector<std::string> order;
    try {
        order = g.topologicalOrder();
    } catch (const std::exception&) {
        for (const auto& n : g.nodes()) order.push_back(n.name);  // a cycle: one column
    }
    for (const auto& name : order) {
        int d = 0;
        for (const auto& e : g.edgesInto(name))
            if (depth.count(e.from.node)) d = std::max(d, depth[e.from.node] + 1);
        depth[name] = d;
    }
    // Stacked by their drawn height (title, one row per port, the time
    // badge above), so tall nodes never overlap the next one.
    std::map<int, double> next;
    for (const auto& n : g.nodes()) {
        if (nodePosition(n)) continue;
        const int d = depth[n.name];
        setNodePosition(g, n.name, QPointF(d * 300.0, next[d]));
        const auto& ports = g.ports(n);
        next[d] += 34 + 26.0 * double(ports.inputs.size() + ports.outputs.size()) + 8 + 40;
    }
}

}  // namespace editor
