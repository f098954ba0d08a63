#include <darkroom/core/yaml_guard.h>

#include <darkroom/atomic_file.h>
#include <darkroom/error.h>
#include <darkroom/input_file.h>
#include <darkroom/core/pipeline.h>
#include <darkroom/strings.h>

#include <yaml-cpp/yaml.h>

#include <cctype>
#include <fstream>
#include <sstream>

namespace darkroom {

namespace {

std::string at(const std::string& source, const YAML::Mark& m) {
    if (m.is_null()) return source;
    return source + ":" + std::to_string(m.line + 1) + ":" + std::to_string(m.column + 1);
}

struct Reader {
    const std::string& source;
    Diagnostics& diags;

    void error(const YAML::Mark& m, std::string msg, const std::string& node = {}) {
        Diagnostic d;
        d.where = at(source, m);
        d.message = std::move(msg);
        d.node = node;
        diags.push_back(std::move(d));
    }
    void warning(const YAML::Mark& m, std::string msg, const std::string& node = {}) {
        error(m, std::move(msg), node);
        diags.back().severity = Diagnostic::Severity::Warning;
    }
};

bool needsQuotes(const std::string& s);
std::string quoted(const std::string& s);
std::string doubleQuoted(const std::string& s);

// One-line YAML text for a value the host does not interpret (placeholder
// parameters, editor layout), so saving writes back what was read. Scalars
// that were quoted, or that would not survive as plain text, stay quoted.
std::string flowText(const YAML::Node& n, bool inFlow = false) {
    if (n.IsScalar()) {
        const std::string& s = n.Scalar();
        const bool wasQuoted = n.Tag() == "!";
        const bool flowUnsafe = inFlow && s.find_first_of(",[]{}") != std::string::npos;
        // Quoted with escapes: a value with a comma and a quote or a
        // backslash once came out as invalid YAML.
        if ((wasQuoted && needsQuotes(s)) || flowUnsafe) return doubleQuoted(s);
        return s;
    }
    if (n.IsSequence()) {
        std::string out = "[";
        for (std::size_t i = 0; i < n.size(); ++i) out += (i ? ", " : "") + flowText(n[i], true);
        return out + "]";
    }
    if (n.IsMap()) {
        std::string out = "{";
        bool first = true;
        for (auto it = n.begin(); it != n.end(); ++it) {
            out += (first ? "" : ", ") + flowText(it->first, true) + ": " + flowText(it->second, true);
            first = false;
        }
        return out + "}";
    }
    return "null";
}

// Value text for typed ports: sequences become "[a, b, c]" for parseValue.
bool scalarText(const YAML::Node& n, std::string& out) {
    if (n.IsScalar()) {
        out = n.Scalar();
        return true;
    }
    if (n.IsSequence()) {
        out = "[";
        for (std::size_t i = 0; i < n.size(); ++i) {
            if (!n[i].IsScalar()) return false;
            out += (i ? ", " : "") + n[i].Scalar();
        }
        out += "]";
        return true;
    }
    return false;
}

bool parseEndpoint(const std::string& text, Endpoint& e) {
    const auto dot = text.find('.');
    if (dot == std::string::npos || dot == 0 || dot + 1 == text.size()) return false;
    e.node = text.substr(0, dot);
    e.port = text.substr(dot + 1);
    auto ok = [](const std::string& s) {
        for (char c : s)
            if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.')) return false;
        return !s.empty();
    };
    return ok(e.node) && ok(e.port);
}

void readNodes(Graph& g, const YAML::Node& nodes, Reader& r) {
    if (!nodes.IsMap()) {
        r.error(nodes.Mark(), "'nodes' must be a map of node name to {type, parameters}");
        return;
    }
    const Registry& registry = g.registry();
    for (auto it = nodes.begin(); it != nodes.end(); ++it) {
        const std::string name = it->first.Scalar();
        const YAML::Node body = it->second;
        if (!body.IsMap()) {
            r.error(body.Mark(), "node '" + name + "' must be a map with 'type' and optional 'parameters'", name);
            continue;
        }
        const YAML::Node type = body["type"];
        if (!type || !type.IsScalar() || type.Scalar().empty()) {
            r.error(body.Mark(), "node '" + name + "' needs a 'type' (e.g. type: ColorMapping)", name);
            continue;
        }
        const Node* n = nullptr;
        try {
            if (registry.filter(type.Scalar())) {
                n = &g.addNode(name, type.Scalar());
            } else {
                n = &g.addPlaceholder(name, type.Scalar());
                r.warning(type.Mark(), "unknown node type '" + type.Scalar() + "' for node '" + name + "'" +
                                           didYouMean(type.Scalar(), registry.typeNames()) +
                                           "; kept as a placeholder (is its plugin loaded?)", name);
            }
        } catch (const Error& e) {
            r.error(it->first.Mark(), e.what(), name);
            continue;
        }
        g.setSourceLocation(name, it->first.Mark().line + 1, it->first.Mark().column + 1);
        for (auto kv = body.begin(); kv != body.end(); ++kv) {
            const std::string key = kv->first.Scalar();
            if (key == "type") continue;
            // Other keys are kept for the editor (ui:), but one that is a
            // misspelling of the host's own would silently lose its content.
            if (key != "parameters" && !nearestName(key, {"type", "parameters"}).empty()) {
                r.error(kv->first.Mark(), "node '" + name + "' has an unknown key '" + key + "'" +
                                              didYouMean(key, {"type", "parameters"}), name);
                continue;
            }
            if (key != "parameters") {
                g.setExtra(name, key, flowText(kv->second));
                continue;
            }
            const YAML::Node params = kv->second;
            if (params.IsNull()) continue;
            if (!params.IsMap()) {
                r.error(params.Mark(), "'parameters' of node '" + name + "' must be a map of port: value", name);
                continue;
            }
            const std::string nodeName = n->name;
            for (auto p = params.begin(); p != params.end(); ++p) {
                const std::string port = p->first.Scalar();
                const Node* cur = g.node(nodeName);
                if (cur->placeholder) {
                    g.setRawParameter(nodeName, port, flowText(p->second));
                    continue;
                }
                const PortSpec* spec = g.ports(*cur).input(port);
                if (!spec) {
                    std::string names;
                    std::vector<std::string> valid;
                    for (const auto& in : g.ports(*cur).inputs)
                        if (in.type != PortType::Image) {
                            names += (names.empty() ? "" : ", ") + in.name;
                            valid.push_back(in.name);
                        }
                    r.error(p->first.Mark(), "node '" + name + "' (" + cur->type + ") has no parameter '" + port +
                                                 "'" + didYouMean(port, valid) +
                                                 "; parameters: " + (names.empty() ? "none" : names), name);
                    continue;
                }
                std::string text;
                if (!scalarText(p->second, text)) {
                    r.error(p->second.Mark(), "parameter '" + port + "' of node '" + name + "' expects a " +
                                                  toString(spec->type) + " value", name);
                    continue;
                }
                try {
                    g.setParameter(nodeName, port, parseValue(spec->type, text));
                } catch (const Error& e) {
                    r.error(p->second.Mark(), "node '" + name + "', parameter '" + port + "': " + e.what(), name);
                }
            }
        }
    }
}

void readEdges(Graph& g, const YAML::Node& edges, Reader& r) {
    if (!edges.IsSequence()) {
        r.error(edges.Mark(), "'edges' must be a list of 'node.port -> node.port'");
        return;
    }
    for (const auto& e : edges) {
        const YAML::Mark m = e.Mark();
        if (!e.IsScalar()) {
            r.error(m, "an edge must be written 'node.port -> node.port'");
            continue;
        }
        const std::string text = e.Scalar();
        const auto arrow = text.find("->");
        Endpoint from, to;
        if (arrow == std::string::npos || !parseEndpoint(std::string(trimBlanks(text.substr(0, arrow))), from) ||
            !parseEndpoint(std::string(trimBlanks(text.substr(arrow + 2))), to)) {
            r.error(m, "cannot read edge '" + text + "'; expected 'node.port -> node.port'");
            continue;
        }
        const Node* a = g.node(from.node);
        const Node* b = g.node(to.node);
        if (!a || !b) {
            r.error(m, "edge '" + text + "' names a node that does not exist: '" + (a ? to.node : from.node) + "'",
                    a ? to.node : from.node);
            continue;
        }
        if (a->placeholder || b->placeholder) {
            g.addEdgeUnchecked({from, to});  // kept; validate() reports the unknown type
            continue;
        }
        std::string why;
        if (!g.canConnect(from, to, &why)) {
            r.error(m, "edge '" + text + "': " + why, to.node);
            continue;
        }
        g.addEdgeUnchecked({from, to});
    }
}

// Plain YAML scalars that would read back as something other than this string.
bool needsQuotes(const std::string& s) {
    if (s.empty()) return true;
    if (s.front() == ' ' || s.back() == ' ') return true;
    if (std::string("-?:,[]{}#&*!|>'\"%@`").find(s.front()) != std::string::npos) return true;
    if (s.find(": ") != std::string::npos || s.find(" #") != std::string::npos || s.back() == ':') return true;
    for (char c : s)
        if (c == '\n' || c == '\t' || c == '\r' || static_cast<unsigned char>(c) < 0x20) return true;
    std::string lower;
    for (char c : s) lower += char(std::tolower(static_cast<unsigned char>(c)));
    static const char* special[] = {"true", "false", "yes", "no", "on", "off", "null", "~", "y", "n"};
    for (const char* w : special)
        if (lower == w) return true;
    // Anything YAML could take for a number.
    try {
        std::size_t used = 0;
        (void)std::stod(s, &used);
        if (used == s.size()) return true;
    } catch (...) {
    }
    return lower == ".inf" || lower == "-.inf" || lower == ".nan";
}

std::string quoted(const std::string& s) { return needsQuotes(s) ? doubleQuoted(s) : s; }

std::string doubleQuoted(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        switch (c) {
            case '"': out += "\\\""; break;
            case '\\': out += "\\\\"; break;
            case '\n': out += "\\n"; break;
            case '\t': out += "\\t"; break;
            case '\r': out += "\\r"; break;
            default: out += c;
        }
    }
    return out + "\"";
}

}  // namespace

Graph parsePipeline(const std::string& text, const std::string& sourceName, const Registry& registry,
                    Diagnostics& diagnostics) {
    Graph g(registry);
    Reader r{sourceName, diagnostics};
    YAML::Node root;
    try {
        root = yamlguard::load(text);
    } catch (const YAML::Exception& e) {
        r.error(e.mark, "malformed YAML: " + e.msg);
        return g;
    }
    if (!root.IsMap()) {
        r.error(root.Mark(), "a pipeline must be a map with 'darkroom', 'nodes' and 'edges'");
        return g;
    }
    try {
        const YAML::Node version = root["darkroom"];
        if (!version) {
            r.error(root.Mark(), "missing the format version; the first line should be 'darkroom: " +
                                     std::to_string(kPipelineFormatVersion) + "'");
        } else {
            int v = 0;
            try {
                v = version.as<int>();
            } catch (const YAML::Exception&) {
                r.error(version.Mark(), "format version must be an integer, got '" + flowText(version) + "'");
            }
            if (v > kPipelineFormatVersion)
                r.error(version.Mark(), "pipeline format version " + std::to_string(v) +
                                            " is newer than this Darkroom supports (" +
                                            std::to_string(kPipelineFormatVersion) + ")");
            else if (v < 1 && version.IsScalar())
                r.error(version.Mark(), "pipeline format version must be at least 1");
        }
        for (auto it = root.begin(); it != root.end(); ++it) {
            const std::string key = it->first.Scalar();
            if (key != "darkroom" && key != "nodes" && key != "edges")
                r.error(it->first.Mark(), "unknown top-level key '" + key + "'" +
                                              didYouMean(key, {"darkroom", "nodes", "edges"}) +
                                              " (expected darkroom, nodes and edges)");
        }
        if (const YAML::Node nodes = root["nodes"]) readNodes(g, nodes, r);
        if (const YAML::Node edges = root["edges"]) readEdges(g, edges, r);
    } catch (const YAML::Exception& e) {
        r.error(e.mark, e.msg);
    }
    return g;
}

Graph loadPipeline(const std::string& path, const Registry& registry, Diagnostics& diagnostics) {
    std::string text;
    try {
        // Refuses FIFOs, devices, directories and files over --max-input-bytes.
        text = readInputFile(path, "pipeline");
    } catch (const Error& e) {
        Diagnostic d;
        d.where = path;
        d.message = e.what();
        // The message names the path already; keep one mention of it.
        if (d.message.rfind(path + ": ", 0) == 0) d.message = d.message.substr(path.size() + 2);
        diagnostics.push_back(d);
        return Graph(registry);
    }
    return parsePipeline(text, path, registry, diagnostics);
}

std::optional<std::set<std::string>> pipelineNodeTypes(const std::string& path) {
    try {
        const YAML::Node root = YAML::Load(readInputFile(path, "pipeline"));
        const YAML::Node nodes = root["nodes"];
        if (!nodes || !nodes.IsMap()) return std::nullopt;
        std::set<std::string> types;
        for (const auto& n : nodes) {
            const YAML::Node type = n.second.IsMap() ? n.second["type"] : YAML::Node();
            if (!type || !type.IsScalar()) return std::nullopt;
            types.insert(type.Scalar());
        }
        return types;
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

std::string serializePipeline(const Graph& g) {
    std::ostringstream out;
    out << "darkroom: " << kPipelineFormatVersion << "\n";
    if (g.nodes().empty()) out << "nodes: {}\n";
    else out << "nodes:\n";
    for (const auto& n : g.nodes()) {
        out << "  " << n.name << ":\n";
        out << "    type: " << quoted(n.type) << "\n";
        if (n.placeholder && !n.rawParameterOrder.empty()) {
            out << "    parameters:\n";
            for (const auto& k : n.rawParameterOrder)
                out << "      " << quoted(k) << ": " << n.rawParameters.at(k) << "\n";
        } else if (!n.placeholder && !n.parameters.empty()) {
            out << "    parameters:\n";
            const PortList& ports = g.ports(n);
            for (const auto& [k, v] : n.parameters) {
                const PortSpec* spec = ports.input(k);
                const PortType t = spec ? spec->type : PortType::String;
                const std::string text = formatValue(t, v);
                const bool list = t == PortType::Color || t == PortType::Vec3;
                const bool number = t == PortType::Float || t == PortType::Int || t == PortType::Bool;
                out << "      " << k << ": " << (list || number ? text : quoted(text)) << "\n";
            }
        }
        for (const auto& [k, v] : n.extras) out << "    " << quoted(k) << ": " << v << "\n";
    }
    if (g.edges().empty()) out << "edges: []\n";
    else out << "edges:\n";
    for (const auto& e : g.edges()) out << "  - " << e.from.str() << " -> " << e.to.str() << "\n";
    return out.str();
}

void savePipeline(const Graph& graph, const std::string& path) {
    writeFileAtomic(path, serializePipeline(graph));
}

}  // namespace darkroom
