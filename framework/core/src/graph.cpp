#include <darkroom/error.h>
#include <darkroom/core/graph.h>
#include <darkroom/strings.h>

#include <algorithm>
#include <cctype>
#include <tuple>
#include <atomic>
#include <cmath>
#include <optional>
#include <functional>
#include <map>
#include <set>
#include <unordered_map>
#include <unordered_set>

namespace darkroom {

namespace {
const PortList kNoPorts;

Diagnostic nodeError(const std::string& node, std::string message,
                     Diagnostic::Severity severity = Diagnostic::Severity::Error) {
    Diagnostic d;
    d.severity = severity;
    d.where = "node '" + node + "'";
    d.message = std::move(message);
    d.node = node;
    return d;
}

// A parameter a user wrote (pipeline file, --set, the editor). checkValue
// lets NaN through, because values flowing along edges may be NaN (a colour
// range of no data); a written NaN, or an infinity, compares false with
// both ends of a declared range and would pass it unchecked.
void checkParameter(const PortSpec& spec, const Value& v) {
    checkValue(spec, v);
    if (spec.type != PortType::Float || (!spec.minimum && !spec.maximum)) return;
    const double d = v.asFloat();
    if (std::isfinite(d)) return;
    auto bound = [](const std::optional<double>& b, const char* none) {
        return b ? formatValue(PortType::Float, Value(*b)) : std::string(none);
    };
    throw Error("port '" + spec.name + "': " + formatValue(PortType::Float, v) + " is not a number in the allowed range [" +
                bound(spec.minimum, "-inf") + ", " + bound(spec.maximum, "inf") + "]");
}

std::string portNames(const std::vector<PortSpec>& ports) {
    std::string s;
    for (const auto& p : ports) s += (s.empty() ? "" : ", ") + p.name;
    return s.empty() ? "none" : s;
}
}  // namespace

bool compatible(PortType from, PortType to) {
    if (from == to) return true;
    if (from == PortType::Int && to == PortType::Float) return true;
    auto stringy = [](PortType t) {
        return t == PortType::String || t == PortType::Path || t == PortType::OutputPath || t == PortType::Enum ||
               t == PortType::ColorMap;
    };
    return stringy(from) && (to == PortType::String || to == PortType::Path || to == PortType::OutputPath);
}

Value asPortValue(PortType type, Value v) {
    if (type == PortType::Float && std::holds_alternative<std::int64_t>(v.storage())) return Value(v.asFloat());
    if (type == PortType::Row && std::holds_alternative<std::string>(v.storage())) return Value(parseRow(v.asString()));
    return v;
}

Graph::Graph(const Registry& registry) : registry_(&registry) {}

void Graph::touch() { ++revision_; }

const Node& Graph::addNode(const std::string& name, const std::string& type) {
    if (!registry_->filter(type))
        throw Error("unknown node type '" + type + "'" + didYouMean(type, registry_->typeNames()) +
                    "; `darkroom plugins` lists the available types");
    addPlaceholder(name, type);
    nodes_.back().placeholder = false;
    return nodes_.back();
}

const Node& Graph::addCopy(const Node& node) {
    if (node.placeholder) addPlaceholder(node.name, node.type);
    else addNode(node.name, node.type);
    nodes_.back() = node;
    return nodes_.back();
}

const Node& Graph::addPlaceholder(const std::string& name, const std::string& type) {
    if (name.empty()) throw Error("a node needs a name");
    for (char c : name)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-'))
            throw Error("node name '" + name + "' may contain only letters, digits, '_' and '-'");
    if (node(name)) throw Error("a node named '" + name + "' already exists");
    Node n;
    n.name = name;
    n.type = type;
    n.placeholder = true;
    nodes_.push_back(std::move(n));
    nodeIndex_[name] = nodes_.size() - 1;
    touch();
    return nodes_.back();
}

void Graph::removeNode(const std::string& name) {
    auto it = std::find_if(nodes_.begin(), nodes_.end(), [&](const Node& n) { return n.name == name; });
    if (it == nodes_.end()) throw Error("no node named '" + name + "'");
    std::erase_if(edges_, [&](const Edge& e) { return e.from.node == name || e.to.node == name; });
    nodes_.erase(it);
    reindex();
    touch();
}

void Graph::renameNode(const std::string& from, const std::string& to) {
    Node* n = &mutableNode(from);
    if (from == to) return;
    if (node(to)) throw Error("a node named '" + to + "' already exists");
    n->name = to;
    for (auto& e : edges_) {
        if (e.from.node == from) e.from.node = to;
        if (e.to.node == from) e.to.node = to;
    }
    reindex();
    touch();
}

void Graph::reindex() {
    nodeIndex_.clear();
    edgesFrom_.clear();
    edgesTo_.clear();
    for (std::size_t i = 0; i < nodes_.size(); ++i) nodeIndex_[nodes_[i].name] = i;
    for (std::size_t i = 0; i < edges_.size(); ++i) {
        edgesFrom_[edges_[i].from.node].push_back(i);
        edgesTo_[edges_[i].to.node].push_back(i);
    }
}

const Node* Graph::node(const std::string& name) const {
    const auto it = nodeIndex_.find(name);
    return it == nodeIndex_.end() ? nullptr : &nodes_[it->second];
}

Node& Graph::mutableNode(const std::string& name) {
    const auto it = nodeIndex_.find(name);
    if (it == nodeIndex_.end()) throw Error("no node named '" + name + "'");
    return nodes_[it->second];
}

const PortList& Graph::ports(const Node& n) const {
    if (n.placeholder) return kNoPorts;
    return registry_->ports(n.type);
}

void Graph::setParameter(const std::string& nodeName, const std::string& port, Value value) {
    Node* n = &mutableNode(nodeName);
    if (n->placeholder) throw Error("node '" + nodeName + "' has unknown type '" + n->type + "'");
    const PortList& ports = this->ports(*n);
    const PortSpec* spec = ports.input(port);
    if (!spec)
        throw Error("node '" + nodeName + "' (" + n->type + ") has no input '" + port +
                    "'; inputs: " + portNames(ports.inputs));
    if (spec->type == PortType::Image)
        throw Error("node '" + nodeName + "': input '" + port + "' is an image; connect it instead");
    value = asPortValue(spec->type, std::move(value));
    checkParameter(*spec, value);
    for (auto& [k, v] : n->parameters)
        if (k == port) {
            if (v == value) return;  // unchanged: keep the cache
            v = std::move(value);
            touch();
            return;
        }
    n->parameters.emplace_back(port, std::move(value));
    touch();
}

void Graph::clearParameter(const std::string& nodeName, const std::string& port) {
    Node& n = mutableNode(nodeName);
    const auto before = n.parameters.size();
    std::erase_if(n.parameters, [&](const auto& kv) { return kv.first == port; });
    if (n.parameters.size() != before) touch();
}

void Graph::setRawParameter(const std::string& nodeName, const std::string& port, std::string yamlText) {
    Node& n = mutableNode(nodeName);
    if (!n.placeholder) throw Error("node '" + nodeName + "' is not a placeholder; set its parameters as values");
    if (!n.rawParameters.count(port)) n.rawParameterOrder.push_back(port);
    n.rawParameters[port] = std::move(yamlText);
    touch();
}

void Graph::setExtra(const std::string& nodeName, const std::string& key, const std::string& yamlText) {
    auto& extras = mutableNode(nodeName).extras;
    const auto it = std::find_if(extras.begin(), extras.end(), [&](const auto& kv) { return kv.first == key; });
    if (yamlText.empty()) {
        if (it != extras.end()) extras.erase(it);
    } else if (it != extras.end()) {
        it->second = yamlText;
    } else {
        extras.emplace_back(key, yamlText);
    }
}

void Graph::clearExtras(const std::string& nodeName) { mutableNode(nodeName).extras.clear(); }

void Graph::setSourceLocation(const std::string& nodeName, int line, int column) {
    Node& n = mutableNode(nodeName);
    n.line = line;
    n.column = column;
}

bool Graph::canConnect(const Endpoint& from, const Endpoint& to, std::string* why) const {
    auto fail = [&](std::string m) {
        if (why) *why = std::move(m);
        return false;
    };
    const Node* a = node(from.node);
    const Node* b = node(to.node);
    if (!a) return fail("no node named '" + from.node + "'");
    if (!b) return fail("no node named '" + to.node + "'");
    if (from.node == to.node) return fail("a node cannot feed itself");
    if (a->placeholder || b->placeholder)
        return fail("node '" + (a->placeholder ? a->name : b->name) + "' has unknown type '" +
                    (a->placeholder ? a->type : b->type) + "'");
    const PortList& pa = ports(*a);
    const PortList& pb = ports(*b);
    const PortSpec* out = pa.output(from.port);
    const PortSpec* in = pb.input(to.port);
    if (!out)
        return fail("node '" + from.node + "' (" + a->type + ") has no output '" + from.port +
                    "'; outputs: " + portNames(pa.outputs));
    if (!in)
        return fail("node '" + to.node + "' (" + b->type + ") has no input '" + to.port +
                    "'; inputs: " + portNames(pb.inputs));
    if (!compatible(out->type, in->type))
        return fail("cannot connect " + from.str() + " (" + toString(out->type) + ") to " + to.str() +
                    " (" + toString(in->type) + "): types differ");
    if (auto it = edgesTo_.find(to.node); it != edgesTo_.end())
        for (const std::size_t i : it->second) {
            const Edge& e = edges_[i];
            if (e.from == from && e.to == to) return fail("already connected");
            if (e.to == to && !in->multiple)
                return fail("input " + to.str() + " is already connected to " + e.from.str());
        }
    if (closesCycle(from.node, to.node))
        return fail("connecting " + from.str() + " to " + to.str() + " would create a cycle");
    return true;
}

void Graph::connect(const Endpoint& from, const Endpoint& to) {
    std::string why;
    if (!canConnect(from, to, &why)) throw Error(why);
    addEdgeUnchecked({from, to});
}

void Graph::addEdgeUnchecked(const Edge& e) {
    edges_.push_back(e);
    edgesFrom_[e.from.node].push_back(edges_.size() - 1);
    edgesTo_[e.to.node].push_back(edges_.size() - 1);
    touch();
}

void Graph::disconnect(const Endpoint& from, const Endpoint& to) {
    const auto before = edges_.size();
    std::erase_if(edges_, [&](const Edge& e) { return e.from == from && e.to == to; });
    if (edges_.size() == before) throw Error("no connection from " + from.str() + " to " + to.str());
    reindex();
    touch();
}

std::vector<Edge> Graph::edgesInto(const std::string& n, const std::string& port) const {
    std::vector<Edge> out;
    if (auto it = edgesTo_.find(n); it != edgesTo_.end())
        for (const std::size_t i : it->second)
            if (edges_[i].to.port == port) out.push_back(edges_[i]);
    return out;
}

std::vector<Edge> Graph::edgesInto(const std::string& n) const {
    std::vector<Edge> out;
    if (auto it = edgesTo_.find(n); it != edgesTo_.end())
        for (const std::size_t i : it->second) out.push_back(edges_[i]);
    return out;
}

bool Graph::closesCycle(const std::string& from, const std::string& to) const {
    // An edge from -> to closes a cycle if `from` already depends on `to`.
    // Searched from both ends at once (downstream of `to`, upstream of
    // `from`), so a graph built in either order costs little per edge.
    if (from == to) return true;
    std::unordered_set<std::string> down{to}, up{from};
    std::vector<std::string> downQueue{to}, upQueue{from};
    auto step = [&](std::vector<std::string>& queue, std::unordered_set<std::string>& seen,
                    const std::unordered_map<std::string, std::vector<std::size_t>>& index, bool downstream,
                    const std::string& goal) {
        const std::string n = std::move(queue.back());
        queue.pop_back();
        if (auto it = index.find(n); it != index.end())
            for (const std::size_t i : it->second) {
                const std::string& next = downstream ? edges_[i].to.node : edges_[i].from.node;
                if (next == goal) return true;
                if (seen.insert(next).second) queue.push_back(next);
            }
        return false;
    };
    while (!downQueue.empty() && !upQueue.empty()) {
        if (step(downQueue, down, edgesFrom_, true, from)) return true;
        if (!upQueue.empty() && step(upQueue, up, edgesTo_, false, to)) return true;
    }
    return false;
}

Diagnostics Graph::validate() const {
    Diagnostics out;
    for (const auto& n : nodes_) {
        if (n.placeholder) {
            out.push_back(nodeError(n.name, "unknown type '" + n.type + "'" + didYouMean(n.type, registry_->typeNames()) +
                                                ", kept as a placeholder; no loaded plugin provides it"));
            continue;
        }
        const PortList& ports = this->ports(n);
        for (const auto& [k, v] : n.parameters) {
            const PortSpec* spec = ports.input(k);
            if (!spec) {
                out.push_back(nodeError(n.name, "no input '" + k + "'; inputs: " + portNames(ports.inputs)));
                continue;
            }
            try {
                checkParameter(*spec, v);
            } catch (const Error& e) {
                out.push_back(nodeError(n.name, e.what()));
            }
        }
        for (const auto& in : ports.inputs) {
            if (in.type != PortType::Image || in.optional) continue;
            if (edgesInto(n.name, in.name).empty())
                out.push_back(nodeError(n.name, "required input '" + in.name + "' (" + n.type +
                                                    ") is not connected"));
        }
    }
    std::map<Endpoint, int, bool (*)(const Endpoint&, const Endpoint&)> fanIn(
        [](const Endpoint& a, const Endpoint& b) { return std::tie(a.node, a.port) < std::tie(b.node, b.port); });
    for (const auto& e : edges_) {
        const Node* a = node(e.from.node);
        const Node* b = node(e.to.node);
        if (!a || !b) {
            out.push_back(nodeError(a ? e.to.node : e.from.node,
                                    "connection " + e.from.str() + " -> " + e.to.str() + " names a missing node '" +
                                        (a ? e.to.node : e.from.node) + "'"));
            continue;
        }
        if (a->placeholder || b->placeholder) continue;  // reported above
        const PortSpec* out_ = ports(*a).output(e.from.port);
        const PortSpec* in = ports(*b).input(e.to.port);
        if (!out_) {
            out.push_back(nodeError(a->name, "has no output '" + e.from.port + "'; outputs: " +
                                                 portNames(ports(*a).outputs)));
            continue;
        }
        if (!in) {
            out.push_back(nodeError(b->name, "has no input '" + e.to.port + "'; inputs: " +
                                                 portNames(ports(*b).inputs)));
            continue;
        }
        if (!compatible(out_->type, in->type))
            out.push_back(nodeError(b->name, "input '" + in->name + "' (" + toString(in->type) +
                                                 ") cannot take " + e.from.str() + " (" +
                                                 toString(out_->type) + ")"));
        if (++fanIn[e.to] == 2 && !in->multiple)
            out.push_back(nodeError(b->name, "input '" + in->name + "' has more than one connection"));
    }
    try {
        (void)topologicalOrder();
    } catch (const Error& e) {
        Diagnostic d;
        d.where = "graph";
        d.message = e.what();
        out.push_back(d);
    }
    return out;
}

std::vector<std::string> Graph::topologicalOrder() const {
    // Depth-first over the edges into each node, without recursion (a long
    // chain would otherwise take as many stack frames as it has nodes).
    std::unordered_map<std::string, int> state;  // 0 new, 1 on stack, 2 done
    std::vector<std::string> order;
    struct Frame {
        const std::string* name;
        std::size_t next = 0;  // position in its list of incoming edges
    };
    std::vector<Frame> stack;
    static const std::vector<std::size_t> kNone;
    auto incoming = [&](const std::string& n) -> const std::vector<std::size_t>& {
        auto it = edgesTo_.find(n);
        return it == edgesTo_.end() ? kNone : it->second;
    };
    for (const auto& root : nodes_) {
        if (state[root.name] != 0) continue;
        state[root.name] = 1;
        stack.push_back({&root.name});
        while (!stack.empty()) {
            Frame& f = stack.back();
            const auto& in = incoming(*f.name);
            if (f.next == in.size()) {
                state[*f.name] = 2;
                order.push_back(*f.name);
                stack.pop_back();
                continue;
            }
            const std::string& up = edges_[in[f.next++]].from.node;
            if (!node(up)) continue;
            int& s = state[up];
            if (s == 2) continue;
            if (s == 1) {
                std::string cycle;
                auto it = std::find_if(stack.begin(), stack.end(), [&](const Frame& x) { return *x.name == up; });
                for (; it != stack.end(); ++it) cycle += *it->name + " -> ";
                throw Error("cycle in the graph: " + cycle + up);
            }
            s = 1;
            stack.push_back({&up});
        }
    }
    return order;
}

std::vector<std::string> Graph::sinks() const {
    std::vector<std::string> out;
    for (const auto& n : nodes_) {
        if (n.placeholder) continue;
        const PortList& p = ports(n);
        const bool writes = std::any_of(p.inputs.begin(), p.inputs.end(),
                                        [](const PortSpec& in) { return in.type == PortType::OutputPath; });
        if (p.outputs.empty() || writes) out.push_back(n.name);
    }
    return out;
}

std::set<std::string> Graph::reachable(const std::vector<std::string>& from, const EdgeIndex& index,
                                       bool downstream) const {
    std::set<std::string> seen;
    std::vector<std::string> todo(from.rbegin(), from.rend());
    while (!todo.empty()) {
        std::string n = std::move(todo.back());
        todo.pop_back();
        if (!node(n) || !seen.insert(n).second) continue;
        if (auto it = index.find(n); it != index.end())
            for (const std::size_t i : it->second)
                todo.push_back(downstream ? edges_[i].to.node : edges_[i].from.node);
    }
    return seen;
}

std::set<std::string> Graph::upstreamOf(const std::vector<std::string>& from) const {
    return reachable(from, edgesTo_, false);
}

std::set<std::string> Graph::downstreamOf(const std::vector<std::string>& from) const {
    return reachable(from, edgesFrom_, true);
}

}  // namespace darkroom
