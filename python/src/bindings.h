#pragma once
// The parts of the native module `_darkroom`, each bound in its own file;
// the Python package (python/darkroom/__init__.py) builds on them.
#include <pybind11/pybind11.h>

namespace darkroom {
class Registry;
}

namespace darkroom::python {

// The process's one registry (the runner's and the editor's kind): filled
// once by `_darkroom.load_plugins`, kept until the process ends, since
// plugins are never unloaded.
Registry& registry();

void bindErrors(pybind11::module_& m);
void bindImage(pybind11::module_& m);
void bindDatabase(pybind11::module_& m);
void bindPipeline(pybind11::module_& m);
void bindInsitu(pybind11::module_& m);
void bindWriter(pybind11::module_& m);
void bindPythonFilters(pybind11::module_& m);
void bindMeshes(pybind11::module_& m);

}  // namespace darkroom::python
