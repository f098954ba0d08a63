// darkroom.DatabaseWriter: a Cinema database written from Python with
// CinemaWriter's guarantees (the data library's writer, as the node and
// `darkroom capture` use it): each product and data.csv written atomically,
// the folder locked while open, an existing one refused unless overwritten
// or resumed, a resume keeping the entries already there.
#include "bindings.h"
#include "image.h"

#include <darkroom/error.h>
#include <darkroom/data/cinema/writer.h>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <memory>

namespace py = pybind11;

namespace darkroom::python {

namespace {

class PyWriter {
public:
    PyWriter(const std::filesystem::path& path, const std::vector<std::string>& columns, const std::string& format,
             const std::string& mode) {
        CinemaWriterOptions o;
        if (format != "exr" && format != "png" && format != "h5")
            throw py::value_error("format: expected 'exr' (every channel), 'png' (colour) or 'h5' (pycinema's HDF5), "
                                  "got '" + format + "'");
        o.productExtension = "." + format;
        if (mode == "overwrite") o.overwrite = true;
        else if (mode == "resume") o.resume = true;
        else if (mode != "create")
            throw py::value_error("mode: expected 'create', 'overwrite' or 'resume', got '" + mode + "'");
        writer_ = std::make_unique<CinemaWriter>(path.string(), columns, o);
    }
    bool has(const py::dict& row) const { return open().hasEntry(parameters(row)); }
    void add(const py::dict& row, const Image& image) {
        const CinemaParameters p = parameters(row);
        py::gil_scoped_release unlocked;
        open().addEntry(p, *image.buffer);
    }
    void finish() {
        if (writer_) writer_->finish();
        writer_.reset();
    }

private:
    CinemaWriter& open() const {
        if (!writer_) throw Error("the database writer is finished; open a new one to add entries");
        return *writer_;
    }
    static CinemaParameters parameters(const py::dict& row) {
        CinemaParameters p;
        for (const auto& [k, v] : row) {
            const std::string column = py::str(k);
            if (py::isinstance<py::bool_>(v) || py::isinstance<py::str>(v)) p.emplace(column, CinemaValue(std::string(py::str(v))));
            else if (py::isinstance<py::int_>(v) || py::isinstance<py::float_>(v) || py::hasattr(v, "__float__"))
                p.emplace(column, CinemaValue(v.cast<double>()));
            else
                throw py::type_error("column '" + column + "': expected a number or a str");
        }
        return p;
    }
    std::unique_ptr<CinemaWriter> writer_;
};

}  // namespace

void bindWriter(py::module_& m) {
    py::class_<PyWriter>(m, "DatabaseWriter",
                         "Writes a Cinema database: DatabaseWriter(path, columns, format='exr', mode='create'); "
                         "add(row, image) per entry; finish() (or a with block) ends it. Atomic, locked while "
                         "open; mode 'overwrite' replaces a database Darkroom wrote, 'resume' adds to one")
        .def(py::init<const std::filesystem::path&, const std::vector<std::string>&, const std::string&,
                      const std::string&>(),
             py::arg("path"), py::arg("columns"), py::arg("format") = "exr", py::arg("mode") = "create")
        .def("add", &PyWriter::add, py::arg("row"), py::arg("image"),
             "Writes the entry {column: value} (every column, numbers or text) with its image")
        .def("has", &PyWriter::has, py::arg("row"), "Whether the database holds this entry (a resume skips it)")
        .def("finish", &PyWriter::finish, "Writes data.csv a last time and lets the lock go")
        .def("__enter__", [](PyWriter& w) -> PyWriter& { return w; }, py::return_value_policy::reference)
        .def("__exit__", [](PyWriter& w, const py::object&, const py::object&, const py::object&) {
            w.finish();
            return false;
        });
}

}  // namespace darkroom::python
