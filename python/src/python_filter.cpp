// Passes written in Python (`darkroom.Filter` subclasses, python/darkroom/
// _filters.py) registered as node types of the process's registry, usable
// in any pipeline, built in code or loaded from a file. The evaluator runs
// them on its threads: execute() takes the interpreter lock for the Python
// call only, so native passes keep running in parallel meanwhile; one
// Python pass runs at a time (ThreadSafety::Unsafe, the lock would
// serialise them anyway). A Python exception becomes the node's error.
#include "bindings.h"
#include "image.h"
#include "values.h"

#include <darkroom/error.h>
#include <darkroom/filter.h>
#include <darkroom/registrar.h>
#include <darkroom/core/registry.h>

#include <pybind11/stl.h>

#include <memory>

namespace py = pybind11;

namespace darkroom::python {

namespace {

// A Python object shared by filter instances that may be destroyed on the
// evaluator's threads: the reference is dropped under the interpreter lock,
// and not at all once the interpreter is gone.
struct PyRef {
    py::object object;
    explicit PyRef(py::object o) : object(std::move(o)) {}
    ~PyRef() {
        if (!Py_IsInitialized()) {
            object.release();
            return;
        }
        py::gil_scoped_acquire gil;
        object = py::object();
    }
};

class PythonFilter : public Filter {
public:
    PythonFilter(std::shared_ptr<PyRef> cls, PortList ports) : cls_(std::move(cls)), ports_(std::move(ports)) {}
    ~PythonFilter() override {
        if (!instance_ || !Py_IsInitialized()) return;
        py::gil_scoped_acquire gil;
        instance_.reset();
    }
    PortList ports() const override { return ports_; }
    ThreadSafety threadSafety() const override { return ThreadSafety::Unsafe; }
    void execute(Context& ctx) override {
        py::gil_scoped_acquire gil;
        try {
            if (!instance_) instance_ = std::make_unique<py::object>(cls_->object());
            py::dict inputs;
            for (const PortSpec& in : ports_.inputs) inputs[py::str(in.name)] = input(ctx, in);
            publish(ctx, instance_->attr("execute")(**inputs));
        } catch (py::error_already_set& e) {
            // The message as Python prints its last line: "ValueError: ...".
            throw Error(std::string("Python ") + e.what());
        }
    }

private:
    static py::object input(Context& ctx, const PortSpec& in) {
        if (!in.isImage()) return fromValue(in.type, ctx.value(in.name));
        if (in.multiple) {
            py::list images;
            for (const auto& b : ctx.images(in.name)) images.append(py::cast(Image{b}));
            return images;
        }
        const BufferPtr b = ctx.image(in.name);
        return b ? py::cast(Image{b}) : py::none();
    }
    void publish(Context& ctx, const py::object& result) const {
        if (py::isinstance<Image>(result) && ports_.outputs.size() == 1) {
            set(ctx, ports_.outputs.front(), result);
            return;
        }
        if (!py::isinstance<py::dict>(result))
            throw Error("execute() returned " + std::string(py::str(py::type::of(result).attr("__name__"))) +
                        "; expected an Image (one output) or a dict of output name: value");
        for (const auto& [key, value] : result.cast<py::dict>()) {
            const std::string name = py::str(key);
            const PortSpec* out = ports_.output(name);
            if (!out) throw Error("execute() returned '" + name + "', which is not an output");
            set(ctx, *out, value);
        }
    }
    static void set(Context& ctx, const PortSpec& out, const py::handle& value) {
        ctx.setOutput(out.name, toValue(out, value, "output '" + out.name + "'"));
    }

    std::shared_ptr<PyRef> cls_;
    PortList ports_;
    std::unique_ptr<py::object> instance_;
};

PortSpec portOf(const py::dict& d, bool output) {
    PortSpec p;
    p.name = d["name"].cast<std::string>();
    if (!parsePortType(d["type"].cast<std::string>(), p.type))
        throw py::value_error("port '" + p.name + "': unknown type '" + d["type"].cast<std::string>() + "'");
    if (d.contains("doc")) p.doc = d["doc"].cast<std::string>();
    if (d.contains("channels")) p.channels = d["channels"].cast<std::vector<std::string>>();
    if (d.contains("optional")) p.optional = d["optional"].cast<bool>();
    if (d.contains("multiple")) p.multiple = d["multiple"].cast<bool>();
    if (d.contains("choices")) p.choices = d["choices"].cast<std::vector<std::string>>();
    if (d.contains("minimum") && !d["minimum"].is_none()) p.minimum = d["minimum"].cast<double>();
    if (d.contains("maximum") && !d["maximum"].is_none()) p.maximum = d["maximum"].cast<double>();
    if (!output && !p.isImage() && d.contains("default"))
        p.defaultValue = toValue(p, d["default"], "port '" + p.name + "' default");
    return p;
}

// registerBuiltin takes a plain function: the one registration in progress.
FilterInfo* g_pending = nullptr;
void registerPending(Registrar& r) { r.addFilter(std::move(*g_pending)); }

}  // namespace

void bindPythonFilters(py::module_& m) {
    m.def(
        "_register_filter",
        [](const std::string& type, const std::string& category, const std::string& doc, const py::list& inputs,
           const py::list& outputs, const py::object& cls, const std::string& origin) {
            PortList ports;
            for (const auto& d : inputs) ports.inputs.push_back(portOf(d.cast<py::dict>(), false));
            for (const auto& d : outputs) ports.outputs.push_back(portOf(d.cast<py::dict>(), true));
            auto ref = std::make_shared<PyRef>(cls);
            FilterInfo info{type, category, doc, [ref, ports] { return std::make_unique<PythonFilter>(ref, ports); }};
            g_pending = &info;
            registry().registerBuiltin(origin, &registerPending);
            g_pending = nullptr;
        },
        py::arg("type"), py::arg("category"), py::arg("doc"), py::arg("inputs"), py::arg("outputs"), py::arg("cls"),
        py::arg("origin"));
}

}  // namespace darkroom::python
