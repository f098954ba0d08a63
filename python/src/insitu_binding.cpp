// `_darkroom._Capture`: the in situ API (darkroom/insitu.h) for Python, the
// one capture from memory the simulations use. darkroom.capture drives it
// (python/darkroom/_capture.py); arrays must stay alive until capture()
// returns, so they are taken only as C-contiguous float32 / uint32 arrays
// (no converted temporaries) and the Python side keeps them.
#include "bindings.h"

#include <darkroom/error.h>
#include <darkroom/insitu.h>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

namespace py = pybind11;

namespace darkroom::python {

namespace {

using Floats = py::array_t<float, py::array::c_style>;
using Indices = py::array_t<std::uint32_t, py::array::c_style>;

class Capture {
public:
    Capture(const std::string& database, int mode) : s_(darkroom_insitu_open(database.c_str(), mode)) {}
    ~Capture() { darkroom_insitu_close(s_); }
    Capture(const Capture&) = delete;
    Capture& operator=(const Capture&) = delete;

    // Every call's status: BAD_INPUT is the caller's mistake (InputError).
    void check(int status) const {
        if (status == DARKROOM_INSITU_OK) return;
        const std::string what = darkroom_insitu_error(s_);
        if (status == DARKROOM_INSITU_BAD_INPUT) throw InputError(what);
        throw Error(what);
    }
    darkroom_insitu* s() const {
        if (!s_) throw Error("capture: this session is closed");
        return s_;
    }
    void close() {
        const int status = darkroom_insitu_close(s_);
        if (status != DARKROOM_INSITU_OK) {
            // The session is gone; its message with it.
            s_ = nullptr;
            throw Error("capture: the database could not be finished");
        }
        s_ = nullptr;
    }

private:
    darkroom_insitu* s_;
};

const double* vec3(const std::vector<double>& v, const char* what) {
    if (v.size() != 3) throw py::type_error(std::string(what) + ": expected 3 numbers");
    return v.data();
}

}  // namespace

void bindInsitu(py::module_& m) {
    py::class_<Capture>(m, "_Capture")
        .def(py::init<const std::string&, int>(), py::arg("database"), py::arg("mode"))
        .def("set_image", [](Capture& c, int w, int h, double fov, double height) {
            c.check(darkroom_insitu_set_image(c.s(), w, h, fov, height));
        })
        .def("orbit", [](Capture& c, const std::vector<double>& target, double distance, const std::vector<double>& up,
                         const std::vector<double>& phi, const std::vector<double>& theta) {
            c.check(darkroom_insitu_camera_orbit(c.s(), vec3(target, "target"), distance, vec3(up, "up"), phi.data(),
                                                 int(phi.size()), theta.data(), int(theta.size())));
        })
        .def("add_camera", [](Capture& c, const std::vector<double>& position, const std::vector<double>& target,
                              const std::vector<double>& up) {
            c.check(darkroom_insitu_add_camera(c.s(), vec3(position, "position"), vec3(target, "target"),
                                               vec3(up, "up")));
        })
        .def("request", [](Capture& c, const std::vector<std::string>& fields, bool normals, bool objectIds,
                           bool primitiveIds) {
            for (const auto& f : fields) c.check(darkroom_insitu_request_field(c.s(), f.c_str()));
            c.check(darkroom_insitu_request_normals(c.s(), normals));
            c.check(darkroom_insitu_request_ids(c.s(), objectIds, primitiveIds));
        })
        .def("begin_step", [](Capture& c, double time) { c.check(darkroom_insitu_begin_step(c.s(), time)); })
        .def("triangles", [](Capture& c, const std::string& name, const Floats& v, const Indices& t) {
            c.check(darkroom_insitu_triangles(c.s(), name.c_str(), v.data(), 12, v.shape(0), t.data(), t.shape(0)));
        })
        .def("lines", [](Capture& c, const std::string& name, const Floats& v, const Indices& segments,
                         const std::optional<Floats>& radii, float radius) {
            c.check(darkroom_insitu_lines(c.s(), name.c_str(), v.data(), 12, v.shape(0), segments.data(),
                                          segments.shape(0), radii ? radii->data() : nullptr, radius));
        })
        .def("points", [](Capture& c, const std::string& name, const Floats& v, const std::optional<Floats>& radii,
                          float radius) {
            c.check(darkroom_insitu_points(c.s(), name.c_str(), v.data(), 12, v.shape(0),
                                           radii ? radii->data() : nullptr, radius));
        })
        .def("field", [](Capture& c, const std::string& object, const std::string& name, const Floats& values,
                         bool cells) {
            c.check(darkroom_insitu_field(c.s(), object.c_str(), name.c_str(), values.data(), values.size(),
                                          cells ? DARKROOM_INSITU_CELL_DATA : DARKROOM_INSITU_POINT_DATA));
        })
        .def("capture", [](Capture& c) {
            int status;
            {
                py::gil_scoped_release unlocked;
                status = darkroom_insitu_capture(c.s());
            }
            c.check(status);
        })
        .def("rows_written", [](const Capture& c) { return darkroom_insitu_rows_written(c.s()); })
        .def("copied_bytes", [](const Capture& c) { return darkroom_insitu_copied_bytes(c.s()); })
        .def("close", &Capture::close);
}

}  // namespace darkroom::python
