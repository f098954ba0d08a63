// darkroom.Database: a Cinema database as the runner reads it — every kind
// CinemaReader reads, rows chosen with --where's syntax or SQL, an entry read
// through the CinemaReader node itself (the same reader, the same messages).
#include "bindings.h"
#include "image.h"

#include <darkroom/error.h>
#include <darkroom/filter.h>
#include <darkroom/core/registry.h>
#include <darkroom/core/run_filter.h>
#include <darkroom/data/cinema/database.h>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <memory>
#include <mutex>

namespace py = pybind11;

namespace darkroom::python {

namespace {

class PyDatabase {
public:
    explicit PyDatabase(const std::filesystem::path& path)
        : db_(std::make_shared<CinemaDatabase>(CinemaDatabase::open(path.string()))),
          path_(std::filesystem::absolute(db_->path()).lexically_normal().string()) {}

    const std::string& path() const { return path_; }
    std::size_t size() const { return db_->rowCount(); }
    std::vector<std::string> columns(bool files, bool parameters) const {
        std::vector<std::string> out;
        for (const auto& c : db_->columns())
            if ((c.isFile && files) || (!c.isFile && parameters)) out.push_back(c.name);
        return out;
    }
    py::dict row(std::size_t r) const {
        if (r >= db_->rowCount()) throw py::index_error("row " + std::to_string(r) + " of " + std::to_string(size()));
        py::dict d;
        for (std::size_t c = 0; c < db_->columns().size(); ++c) d[py::str(db_->columns()[c].name)] = db_->cell(r, c);
        return d;
    }
    std::vector<std::size_t> select(const std::string& where) const {
        if (where.empty()) {
            std::vector<std::size_t> all(size());
            for (std::size_t r = 0; r < all.size(); ++r) all[r] = r;
            return all;
        }
        return db_->selectWhere(where);
    }
    Image read(const std::optional<std::string>& where, const std::optional<std::int64_t>& entry,
               const std::string& file) {
        std::map<std::string, std::vector<Value>> in{{"database", {Value(path_)}}};
        if (entry) in["entry"] = {Value(*entry)};
        if (where) in["parameters"] = {Value(*where)};
        if (!file.empty()) in["file"] = {Value(file)};
        FilterRunOptions o;
        o.registry = &registry();
        o.nodeName = "Database.read";
        o.nodeType = "CinemaReader";
        std::lock_guard<std::mutex> lock(mutex_);
        // One reader per database: it keeps data.csv parsed between reads.
        if (!reader_) reader_ = registry().createFilter("CinemaReader");
        py::gil_scoped_release unlocked;
        return Image{runFilter(*reader_, in, o).outputs.at("image").asImage()};
    }

private:
    std::shared_ptr<const CinemaDatabase> db_;
    std::string path_;
    std::mutex mutex_;
    std::unique_ptr<Filter> reader_;
};

}  // namespace

void bindDatabase(py::module_& m) {
    py::class_<PyDatabase>(m, "Database",
                           "A Cinema database (a .cdb folder or its data.csv): its rows, and its entries read as "
                           "images by the CinemaReader node")
        .def(py::init<const std::filesystem::path&>(), py::arg("path"))
        .def_property_readonly("path", &PyDatabase::path, "The .cdb folder, absolute")
        .def("__len__", &PyDatabase::size)
        .def_property_readonly("columns", [](const PyDatabase& d) { return d.columns(true, true); },
                               "Every column, in data.csv order")
        .def_property_readonly("parameters", [](const PyDatabase& d) { return d.columns(false, true); },
                               "The parameter columns (not FILE)")
        .def_property_readonly("files", [](const PyDatabase& d) { return d.columns(true, false); },
                               "The FILE columns")
        .def("row", &PyDatabase::row, py::arg("index"), "Row `index` as {column: cell as written}")
        .def("select", &PyDatabase::select, py::arg("where") = "",
             "The row indices matching `where`: 'phi=30, theta=45' (numbers snap) or an SQL WHERE "
             "expression ('phi > 0 AND theta = 0'), as darkroom run --where; empty = every row")
        .def("read", &PyDatabase::read, py::arg("where") = std::nullopt, py::arg("entry") = std::nullopt,
             py::arg("file") = "",
             "An entry as an Image: by `where` (the first row it selects; a composable image set's layer) or by "
             "row number `entry`; `file` picks a FILE column")
        .def("__repr__", [](const PyDatabase& d) {
            return "<darkroom.Database " + d.path() + ": " + std::to_string(d.size()) + " rows>";
        });
}

}  // namespace darkroom::python
