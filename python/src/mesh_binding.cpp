// `_darkroom.read_mesh`: a mesh file through the scene library's readers
// (the formats of scene files: .ply .obj .vtk .vtp .vtu .pvtp .pvtu ...), as
// numpy arrays for darkroom.Scene.add_file: each part with its positions,
// its primitives and its fields, cell fields given per primitive.
#include "bindings.h"

#include <darkroom/scene/mesh_readers.h>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>

namespace py = pybind11;

namespace darkroom::python {

namespace {

py::dict part(const SceneObject& o) {
    const std::size_t n = o.vertexCount();
    py::array_t<float> positions({py::ssize_t(n), py::ssize_t(3)});
    float* p = positions.mutable_data();
    for (std::size_t i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k) p[3 * i + k] = o.vertices[4 * i + k];
    const bool surface = o.representation == Representation::Surface;
    const py::ssize_t columns = surface ? 3 : 1;
    py::array_t<std::uint32_t> indices({py::ssize_t(o.indices.size()) / columns, columns});
    std::copy(o.indices.begin(), o.indices.end(), indices.mutable_data());
    py::dict points, cells;
    const std::size_t primitives = o.primitiveCount();
    for (const ScalarField& f : o.fields) {
        if (f.association == ScalarField::Association::Point) {
            points[py::str(f.name)] = py::array_t<float>(py::ssize_t(f.values.size()), f.values.data());
            continue;
        }
        // Per primitive: a polygon's triangles, a polyline's segments share their cell's value.
        py::array_t<float> v{py::ssize_t(primitives)};
        for (std::size_t i = 0; i < primitives; ++i)
            v.mutable_data()[i] = f.values[o.primitiveCell.empty() ? i : o.primitiveCell[i]];
        cells[py::str(f.name)] = v;
    }
    return py::dict(py::arg("name") = o.name, py::arg("representation") = toString(o.representation),
                    py::arg("positions") = positions, py::arg("indices") = indices,
                    py::arg("point_fields") = points, py::arg("cell_fields") = cells);
}

}  // namespace

void bindMeshes(py::module_& m) {
    m.def(
        "read_mesh",
        [](const std::filesystem::path& path) {
            std::vector<std::string> warnings;
            const std::vector<SceneObject> objects = readMesh(path.string(), &warnings);
            py::list parts;
            for (const auto& o : objects) parts.append(part(o));
            return py::make_tuple(parts, warnings);
        },
        py::arg("path"), "The parts of a mesh file as arrays, and the reader's warnings");
}

}  // namespace darkroom::python
