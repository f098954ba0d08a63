// The native side of darkroom.Pipeline: a graph and the evaluator that keeps
// its cache while the Python object lives, so that after an edit only what
// depends on it runs again (the editor's evaluator, the runner's files).
#include "bindings.h"
#include "values.h"

#include <darkroom/strings.h>
#include <darkroom/error.h>
#include <darkroom/core/evaluator.h>
#include <darkroom/core/pipeline.h>
#include <darkroom/core/registry.h>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cctype>
#include <filesystem>
#include <mutex>

namespace py = pybind11;
namespace fs = std::filesystem;

namespace darkroom::python {

namespace {

class PyPipeline {
public:
    PyPipeline() : graph_(registry()) {}

    void load(const fs::path& path) {
        Diagnostics d;
        Graph g = loadPipeline(path.string(), registry(), d);
        std::string errors;
        for (const auto& x : d)
            if (x.severity == Diagnostic::Severity::Error) errors += (errors.empty() ? "" : "\n") + x.str();
        if (!errors.empty()) throw InputError(errors);
        std::lock_guard<std::mutex> lock(mutex_);
        graph_ = std::move(g);
        setFolder(fs::absolute(path).parent_path());
    }
    void save(const fs::path& path) const { savePipeline(graph_, path.string()); }
    std::string yaml() const { return serializePipeline(graph_); }

    std::string add(const std::string& type, const std::string& wanted) {
        std::string name = wanted;
        if (name.empty()) {
            std::string base;
            for (const char c : type) base += char(std::tolower(static_cast<unsigned char>(c)));
            name = base;
            for (int i = 2; graph_.node(name); ++i) name = base + std::to_string(i);
        }
        std::lock_guard<std::mutex> lock(mutex_);
        graph_.addNode(name, type);
        return name;
    }
    void remove(const std::string& node) {
        std::lock_guard<std::mutex> lock(mutex_);
        graph_.removeNode(node);
    }

    const PortSpec& input(const std::string& node, const std::string& port) const {
        const Node* n = requireNode(node);
        const PortSpec* p = graph_.ports(*n).input(port);
        if (!p) {
            std::vector<std::string> inputs;
            for (const auto& in : graph_.ports(*n).inputs) inputs.push_back(in.name);
            throw py::attribute_error(label(*n) + " has no input '" + port + "'" + didYouMean(port, inputs) +
                                      "; inputs: " + names(graph_.ports(*n).inputs));
        }
        return *p;
    }
    void set(const std::string& node, const std::string& port, const py::handle& value) {
        const PortSpec& p = input(node, port);
        Value v = toValue(p, value, "node '" + node + "' input '" + port + "'");
        std::lock_guard<std::mutex> lock(mutex_);
        graph_.setParameter(node, port, std::move(v));
    }
    py::object get(const std::string& node, const std::string& port) const {
        const PortSpec& p = input(node, port);
        const Value* v = requireNode(node)->parameter(port);
        return fromValue(p.type, v ? *v : p.defaultValue);
    }
    void clear(const std::string& node, const std::string& port) {
        std::lock_guard<std::mutex> lock(mutex_);
        graph_.clearParameter(node, port);
    }
    void connect(const Endpoint& from, const Endpoint& to, bool on) {
        std::lock_guard<std::mutex> lock(mutex_);
        if (on) graph_.connect(from, to);
        else graph_.disconnect(from, to);
    }

    py::list ports(const std::string& node) const {
        const Node* n = requireNode(node);
        py::list out;
        for (const auto* list : {&graph_.ports(*n).inputs, &graph_.ports(*n).outputs})
            for (const PortSpec& p : *list)
                out.append(py::dict(py::arg("name") = p.name, py::arg("type") = toString(p.type),
                                    py::arg("output") = list == &graph_.ports(*n).outputs, py::arg("doc") = p.doc));
        return out;
    }
    std::vector<std::string> nodeNames() const {
        std::vector<std::string> out;
        for (const Node& n : graph_.nodes()) out.push_back(n.name);
        return out;
    }
    std::string nodeType(const std::string& node) const { return requireNode(node)->type; }

    py::object evaluate(const std::string& node, const std::string& port) {
        const Node* n = requireNode(node);
        const PortSpec* out = graph_.ports(*n).output(port);
        if (!out) throw py::attribute_error(label(*n) + " has no output '" + port + "'; outputs: " + names(graph_.ports(*n).outputs));
        const PortType type = out->type;
        Value v;
        {
            // Native passes run on the evaluator's threads meanwhile; the
            // lock (taken without the GIL, let go before it is taken back)
            // keeps another Python thread from editing the graph under it.
            py::gil_scoped_release unlocked;
            std::lock_guard<std::mutex> lock(mutex_);
            v = evaluator_.evaluate(graph_, node, port);
        }
        return fromValue(type, v);
    }
    void run(const std::vector<std::string>& nodes) {
        py::gil_scoped_release unlocked;
        std::lock_guard<std::mutex> lock(mutex_);
        evaluator_.run(graph_, nodes);
    }
    std::vector<std::string> lastRun() const {
        std::vector<std::string> out;
        for (const auto& p : evaluator_.lastProfile())
            if (p.status == NodeProfile::Status::Ran) out.push_back(p.node);
        return out;
    }
    void setFolder(const fs::path& folder) {
        EvaluatorOptions o = evaluator_.options();
        o.inputBase = folder.string();
        evaluator_.setOptions(o);
    }
    void setOutput(const fs::path& folder) {
        EvaluatorOptions o = evaluator_.options();
        o.outputDir = folder.string();
        evaluator_.setOptions(o);
    }

private:
    const Node* requireNode(const std::string& name) const {
        const Node* n = graph_.node(name);
        if (!n) throw py::key_error("no node named '" + name + "'; nodes: " + names(nodeNames()));
        return n;
    }
    static std::string label(const Node& n) { return "node '" + n.name + "' (" + n.type + ")"; }
    static std::string names(const std::vector<PortSpec>& ports) {
        std::string s;
        for (const auto& p : ports) s += (s.empty() ? "" : ", ") + p.name;
        return s.empty() ? "none" : s;
    }
    static std::string names(const std::vector<std::string>& list) {
        std::string s;
        for (const auto& p : list) s += (s.empty() ? "" : ", ") + p;
        return s.empty() ? "none" : s;
    }

    Graph graph_;
    Evaluator evaluator_;
    std::mutex mutex_;
};

}  // namespace

void bindPipeline(py::module_& m) {
    py::class_<PyPipeline>(m, "_Pipeline")
        .def(py::init<>())
        .def("_load", &PyPipeline::load, py::arg("path"))
        .def("save", &PyPipeline::save, py::arg("path"), "Writes the pipeline file (what `darkroom run` reads)")
        .def("to_yaml", &PyPipeline::yaml)
        .def("_add", &PyPipeline::add, py::arg("type"), py::arg("name"))
        .def("remove", &PyPipeline::remove, py::arg("node"))
        .def("set", &PyPipeline::set, py::arg("node"), py::arg("port"), py::arg("value"))
        .def("get", &PyPipeline::get, py::arg("node"), py::arg("port"))
        .def("clear", &PyPipeline::clear, py::arg("node"), py::arg("port"))
        .def("ports", &PyPipeline::ports, py::arg("node"))
        .def_property_readonly("node_names", &PyPipeline::nodeNames)
        .def("node_type", &PyPipeline::nodeType, py::arg("node"))
        .def("_connect", [](PyPipeline& p, const std::string& a, const std::string& ap, const std::string& b,
                            const std::string& bp) { p.connect({a, ap}, {b, bp}, true); })
        .def("_disconnect", [](PyPipeline& p, const std::string& a, const std::string& ap, const std::string& b,
                               const std::string& bp) { p.connect({a, ap}, {b, bp}, false); })
        .def("_evaluate", &PyPipeline::evaluate, py::arg("node"), py::arg("port"))
        .def("run", &PyPipeline::run, py::arg("nodes") = std::vector<std::string>{},
             "Runs the given nodes (default: every sink, as `darkroom run`) and what they need")
        .def_property_readonly("last_run", &PyPipeline::lastRun,
                               "The nodes the last evaluation executed (the others came from the cache)")
        .def("set_folder", &PyPipeline::setFolder, py::arg("folder"),
             "Where relative input paths resolve (a loaded pipeline: its file's folder)")
        .def("set_output", &PyPipeline::setOutput, py::arg("folder"),
             "Where relative output paths resolve (darkroom run --output)");
}

}  // namespace darkroom::python
