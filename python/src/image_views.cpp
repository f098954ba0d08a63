#include "image.h"

#include <darkroom/srgb.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace py = pybind11;

namespace darkroom::python {

py::array channelView(const BufferPtr& buffer, const std::string& channel) {
    const PlanePtr plane = buffer->plane(channel);
    const auto type = buffer->channelType(channel);
    if (!plane || !type) {
        std::string names;
        for (const auto& n : buffer->channelNames()) names += (names.empty() ? "" : ", ") + n;
        throw py::key_error("no channel '" + channel + "'; the image has " + (names.empty() ? "none" : names));
    }
    const py::dtype dtype = *type == ChannelType::Float32 ? py::dtype::of<float>() : py::dtype::of<std::uint32_t>();
    const auto h = py::ssize_t(buffer->height()), w = py::ssize_t(buffer->width());
    // The capsule owns a reference to the plane: the array outlives the image.
    py::capsule owner(new PlanePtr(plane), [](void* p) { delete static_cast<PlanePtr*>(p); });
    py::array view(dtype, {h, w}, {w * 4, py::ssize_t(4)}, plane->data(), owner);
    view.attr("setflags")(py::arg("write") = false);
    return view;
}

namespace {

std::uint8_t encode(float linear) {
    if (!(linear > 0)) return 0;  // NaN too
    return std::uint8_t(std::lround(std::min(1.0f, linearToSrgb(std::min(linear, 1.0f))) * 255.0f));
}

// The first channel as grey over its finite range (a depth, a scalar).
void fillGrey(const Buffer& b, std::uint8_t* out) {
    const std::string name = b.channelNames().front();
    const std::size_t n = b.pixelCount();
    std::vector<float> v(n);
    if (b.channelType(name) == ChannelType::UInt32) {
        const auto* u = static_cast<const std::uint32_t*>(b.plane(name)->data());
        for (std::size_t i = 0; i < n; ++i) v[i] = float(u[i]);
    } else {
        std::copy_n(b.hostFloat(name), n, v.begin());
    }
    float lo = std::numeric_limits<float>::infinity(), hi = -lo;
    for (const float x : v)
        if (std::isfinite(x)) lo = std::min(lo, x), hi = std::max(hi, x);
    const float scale = hi > lo ? 1.0f / (hi - lo) : 0.0f;
    for (std::size_t i = 0; i < n; ++i) {
        const bool ok = std::isfinite(v[i]);
        const auto g = std::uint8_t(ok ? std::lround((v[i] - lo) * scale * 255.0f) : 0);
        out[4 * i] = out[4 * i + 1] = out[4 * i + 2] = g;
        out[4 * i + 3] = ok ? 255 : 0;
    }
}

}  // namespace

py::array_t<std::uint8_t> toRgba8(const Buffer& b) {
    const auto h = py::ssize_t(b.height()), w = py::ssize_t(b.width());
    py::array_t<std::uint8_t> out({h, w, py::ssize_t(4)});
    std::uint8_t* o = out.mutable_data();
    const std::size_t n = b.pixelCount();
    if (b.hasChannel("R") && b.hasChannel("G") && b.hasChannel("B")) {
        const float* c[3] = {b.hostFloat("R"), b.hostFloat("G"), b.hostFloat("B")};
        const float* a = b.hasChannel("A") ? b.hostFloat("A") : nullptr;
        for (std::size_t i = 0; i < n; ++i) {
            for (int k = 0; k < 3; ++k) o[4 * i + k] = encode(c[k][i]);
            o[4 * i + 3] = !a ? 255 : a[i] > 0 ? std::uint8_t(std::lround(std::min(a[i], 1.0f) * 255.0f)) : 0;
        }
    } else if (!b.channels().empty()) {
        fillGrey(b, o);
    } else {
        std::fill_n(o, 4 * n, std::uint8_t(0));
    }
    return out;
}

}  // namespace darkroom::python
