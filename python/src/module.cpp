// `_darkroom`: Darkroom's libraries for Python (docs/python.md).
#include "bindings.h"

#include <darkroom/core/registry.h>
#include <darkroom/version.h>

#include <pybind11/stl.h>

namespace py = pybind11;

namespace darkroom::python {

Registry& registry() {
    // Never destroyed: filters and types the plugins own may be referenced
    // until the interpreter is gone.
    static Registry* r = new Registry();
    return *r;
}

}  // namespace darkroom::python

PYBIND11_MODULE(_darkroom, m) {
    using namespace darkroom::python;
    m.doc() = "Darkroom's native module; use the package `darkroom`";
    bindErrors(m);
    bindImage(m);
    bindDatabase(m);
    bindPipeline(m);
    bindInsitu(m);
    bindWriter(m);
    bindPythonFilters(m);
    bindMeshes(m);
    m.def(
        "load_plugins",
        [](const std::vector<std::string>& searchPath) {
            std::vector<std::string> problems;
            for (const auto& d : registry().loadPlugins(searchPath)) problems.push_back(d.where + ": " + d.message);
            return problems;
        },
        py::arg("search_path"),
        "Loads the plugins of each folder (or file); returns the problems met, one line each");
    m.def("node_types", [] {
        std::vector<std::string> out;
        for (const auto* f : registry().filters()) out.push_back(f->info.type);
        return out;
    }, "The node types the loaded plugins registered, sorted");
    m.def("plugins", [] {
        std::vector<py::dict> out;
        for (const auto& p : registry().plugins())
            out.push_back(py::dict(py::arg("name") = p.origin.plugin, py::arg("version") = p.origin.version,
                                   py::arg("path") = p.origin.path, py::arg("types") = p.types));
        return out;
    }, "The plugins loaded: name, version, path and the types each registered");
    m.attr("__version__") = DARKROOM_SDK_VERSION;
}
