// darkroom.Image and darkroom.Camera.
#include "bindings.h"
#include "image.h"

#include <darkroom/camera.h>
#include <darkroom/error.h>
#include <darkroom/srgb.h>
#include <darkroom/data/image_io.h>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <unistd.h>

namespace py = pybind11;
namespace fs = std::filesystem;

namespace darkroom::python {

namespace {

std::vector<double> list3(const Vec3& v) { return {v.x, v.y, v.z}; }
Vec3 vec3(const std::vector<double>& v, const char* what) {
    if (v.size() != 3) throw py::type_error(std::string(what) + ": expected 3 numbers");
    return {v[0], v[1], v[2]};
}

void bindCamera(py::module_& m) {
    py::class_<Camera>(m, "Camera", "A camera as the G-buffer records it (position, view direction, up, projection)")
        .def(py::init<>())
        .def_property("position", [](const Camera& c) { return list3(c.position); },
                      [](Camera& c, const std::vector<double>& v) { c.position = vec3(v, "position"); })
        .def_property("forward", [](const Camera& c) { return list3(c.forward); },
                      [](Camera& c, const std::vector<double>& v) { c.forward = vec3(v, "forward"); })
        .def_property("up", [](const Camera& c) { return list3(c.up); },
                      [](Camera& c, const std::vector<double>& v) { c.up = vec3(v, "up"); })
        .def_property("orthographic", [](const Camera& c) { return c.projection == Camera::Projection::Orthographic; },
                      [](Camera& c, bool o) {
                          c.projection = o ? Camera::Projection::Orthographic : Camera::Projection::Perspective;
                      })
        .def_readwrite("fov_y_degrees", &Camera::fovYDegrees)
        .def_readwrite("view_height", &Camera::viewHeight)
        .def_readwrite("width", &Camera::width)
        .def_readwrite("height", &Camera::height)
        .def("__eq__", [](const Camera& a, const Camera& b) { return a == b; })
        .def("__repr__", [](const Camera& c) {
            std::ostringstream s;
            s << "Camera(position=[" << c.position.x << ", " << c.position.y << ", " << c.position.z
              << "], forward=[" << c.forward.x << ", " << c.forward.y << ", " << c.forward.z << "], "
              << (c.projection == Camera::Projection::Orthographic ? "orthographic" : "perspective") << ", "
              << c.width << "x" << c.height << ")";
            return s.str();
        });
}

// An image made from arrays of one shape: float32 or uint32 channels, copied in.
Image fromArrays(const py::dict& channels, const std::optional<Camera>& camera,
                 const std::map<std::string, std::string>& metadata) {
    if (channels.empty()) throw py::value_error("channels: give at least one, e.g. {'Z': depth}");
    py::ssize_t h = -1, w = -1;
    std::shared_ptr<WritableBuffer> out;
    for (const auto& [key, value] : channels) {
        const std::string name = py::cast<std::string>(key);
        const py::array a = py::array::ensure(value);
        if (!a || a.ndim() != 2) throw py::type_error("channel '" + name + "': expected a 2-D array (height, width)");
        const bool u32 = a.dtype().kind() == 'u' || (a.dtype().kind() == 'i' && a.dtype().itemsize() == 4);
        const py::array c = u32 ? py::array(py::array_t<std::uint32_t, py::array::c_style | py::array::forcecast>(a))
                                : py::array(py::array_t<float, py::array::c_style | py::array::forcecast>(a));
        if (!out) {
            h = c.shape(0), w = c.shape(1);
            out = makeHostBuffer(int(w), int(h));
        } else if (c.shape(0) != h || c.shape(1) != w) {
            throw py::value_error("channel '" + name + "' is " + std::to_string(c.shape(0)) + " x " +
                                  std::to_string(c.shape(1)) + ", the first was " + std::to_string(h) + " x " +
                                  std::to_string(w));
        }
        auto plane = newHostPlane(std::size_t(h * w), false);
        std::memcpy(plane->writableData(), c.data(), std::size_t(h * w) * 4);
        out->setPlane({name, u32 ? ChannelType::UInt32 : ChannelType::Float32}, plane);
    }
    if (camera) out->metadata().camera = *camera;
    for (const auto& [k, v] : metadata) out->metadata().attributes[k] = v;
    sealPlanes(*out);
    return Image{out};
}

// The image's planes shared, the given channels added or replaced (copied
// in): what a pass written in Python returns, as derive() in C++.
Image withChannels(const Image& image, const py::dict& channels) {
    const Image added = fromArrays(channels, std::nullopt, {});
    const Buffer& in = *image.buffer;
    if (added.buffer->width() != in.width() || added.buffer->height() != in.height())
        throw py::value_error("with_channels: the arrays are " + std::to_string(added.buffer->height()) + " x " +
                              std::to_string(added.buffer->width()) + ", the image " + std::to_string(in.height()) +
                              " x " + std::to_string(in.width()));
    auto out = makeHostBuffer(in.width(), in.height());
    for (const auto& c : in.channels()) out->setPlane(c, in.plane(c.name));
    for (const auto& c : added.buffer->channels()) out->setPlane(c, added.buffer->plane(c.name));
    out->metadata() = in.metadata();
    return Image{out};
}

py::bytes png(const Image& image) {
    // Through the data library's writer (what a PNG CinemaWriter writes), by
    // way of a private temporary file.
    const py::array_t<std::uint8_t> rgba = toRgba8(*image.buffer);
    const int w = image.buffer->width(), h = image.buffer->height();
    auto shown = makeCpuBuffer(w, h, {"R", "G", "B", "A"});
    const std::uint8_t* p = rgba.data();
    float* c[4] = {shown->writeFloat("R"), shown->writeFloat("G"), shown->writeFloat("B"),
                   shown->writeFloat("A")};
    for (std::size_t i = 0; i < std::size_t(w) * std::size_t(h); ++i) {
        for (int k = 0; k < 3; ++k) c[k][i] = srgbToLinear(p[4 * i + k] / 255.0f);
        c[3][i] = p[4 * i + 3] / 255.0f;
    }
    std::string pattern = (fs::temp_directory_path() / "darkroom-repr-XXXXXX").string();
    const int fd = mkstemp(pattern.data());
    if (fd < 0) throw Error("cannot make a temporary file for the picture");
    close(fd);
    const std::string file = pattern + ".png";
    fs::rename(pattern, file);
    std::string bytes;
    try {
        writeImage(*shown, file);
        std::ifstream in(file, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), {});
    } catch (...) {
        fs::remove(file);
        throw;
    }
    fs::remove(file);
    return py::bytes(bytes);
}

}  // namespace

void bindImage(py::module_& m) {
    bindCamera(m);
    py::class_<Image>(m, "Image",
                      "An image with named channels. img['Z'] is a read-only numpy view of the channel: "
                      "no copy, and the view keeps the data alive")
        .def_static("from_arrays", &fromArrays, py::arg("channels"), py::arg("camera") = std::nullopt,
                    py::arg("metadata") = std::map<std::string, std::string>{},
                    "An image from 2-D arrays of one shape, {name: array}; float32 channels, or uint32 for "
                    "unsigned or 32-bit integer arrays (ids). The arrays are copied")
        .def("with_channels", &withChannels, py::arg("channels"),
             "A new image with this one's channels (shared, not copied) and `channels` {name: array} added or "
             "replaced")
        .def_property_readonly("width", [](const Image& i) { return i.buffer->width(); })
        .def_property_readonly("height", [](const Image& i) { return i.buffer->height(); })
        .def_property_readonly("shape", [](const Image& i) { return py::make_tuple(i.buffer->height(), i.buffer->width()); })
        .def_property_readonly("channels", [](const Image& i) { return i.buffer->channelNames(); })
        .def_property_readonly("camera", [](const Image& i) { return i.buffer->metadata().camera; })
        .def_property_readonly("metadata", [](const Image& i) { return i.buffer->metadata().attributes; })
        .def("__getitem__", [](const Image& i, const std::string& c) { return channelView(i.buffer, c); })
        .def("__contains__", [](const Image& i, const std::string& c) { return i.buffer->hasChannel(c); })
        .def("__len__", [](const Image& i) { return i.buffer->channels().size(); })
        .def("to_rgba8", [](const Image& i) { return toRgba8(*i.buffer); },
             "(height, width, 4) uint8: R, G, B sRGB-encoded and A; without colour, the first channel as grey")
        .def("_repr_png_", &png)
        .def("save", [](const Image& i, const fs::path& path) { writeImage(*i.buffer, path.string()); }, py::arg("path"),
             "Writes the image: EXR keeps every channel and the camera; PNG, JPEG, TIFF the colour")
        .def("__repr__", [](const Image& i) {
            std::string names;
            for (const auto& n : i.buffer->channelNames()) names += (names.empty() ? "" : ", ") + n;
            return "<darkroom.Image " + std::to_string(i.buffer->width()) + " x " + std::to_string(i.buffer->height()) +
                   ": " + names + ">";
        });
}

}  // namespace darkroom::python
