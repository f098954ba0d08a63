// Darkroom's errors as Python exceptions, with the same messages (file:line,
// node): darkroom.Error (a RuntimeError) and darkroom.InputError (also a
// ValueError: bad input), each with `node`, the failing node's name or "".
#include "bindings.h"

#include <darkroom/error.h>

namespace py = pybind11;

namespace darkroom::python {

void bindErrors(py::module_& m) {
    static py::exception<Error> error(m, "Error", PyExc_RuntimeError);
    static py::object inputError = [&] {
        py::object bases = py::make_tuple(error, py::handle(PyExc_ValueError));
        py::object type = py::reinterpret_steal<py::object>(
            PyErr_NewException("_darkroom.InputError", bases.ptr(), nullptr));
        m.attr("InputError") = type;
        return type;
    }();
    error.attr("node") = "";
    py::register_exception_translator([](std::exception_ptr p) {
        if (!p) return;
        const auto raise = [](const py::object& type, const Error& e) {
            py::object exc = type(e.what());
            exc.attr("node") = e.node();
            PyErr_SetObject(type.ptr(), exc.ptr());
        };
        try {
            std::rethrow_exception(p);
        } catch (const Cancelled&) {
            PyErr_SetString(PyExc_KeyboardInterrupt, "cancelled");
        } catch (const InputError& e) {
            raise(inputError, e);
        } catch (const Error& e) {
            raise(error, e);
        }
    });
}

}  // namespace darkroom::python
