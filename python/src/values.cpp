#include "values.h"

#include "image.h"

#include <pybind11/stl.h>

#include <cmath>

namespace py = pybind11;

namespace darkroom::python {

namespace {

[[noreturn]] void wrongType(const PortSpec& port, const py::handle& object, const std::string& what,
                            const char* expected) {
    throw py::type_error(what + ": expected " + expected + " (a " + toString(port.type) + " port), got " +
                         std::string(py::str(py::type::of(object).attr("__name__"))));
}

std::vector<double> numbers(const PortSpec& port, const py::handle& o, const std::string& what, const char* expected) {
    if (py::isinstance<py::str>(o) || !py::isinstance<py::sequence>(o)) wrongType(port, o, what, expected);
    std::vector<double> v;
    for (const auto& x : o.cast<py::sequence>()) {
        if (!py::isinstance<py::float_>(x) && !py::isinstance<py::int_>(x) &&
            !py::hasattr(x, "__float__"))
            wrongType(port, o, what, expected);
        v.push_back(x.cast<double>());
    }
    return v;
}

Value rowValue(const PortSpec& port, const py::handle& o, const std::string& what) {
    if (py::isinstance<py::str>(o)) return parseValue(PortType::Row, o.cast<std::string>());
    if (!py::isinstance<py::dict>(o)) wrongType(port, o, what, "a dict of column: value, or 'name=value, ...'");
    std::vector<RowCell> cells;
    for (const auto& [k, v] : o.cast<py::dict>())
        cells.push_back({py::str(k).cast<std::string>(), py::str(v).cast<std::string>()});
    return Value(Row(std::move(cells)));
}

}  // namespace

Value toValue(const PortSpec& port, const py::handle& o, const std::string& what) {
    const bool isBool = py::isinstance<py::bool_>(o);
    const bool isNumber = !isBool && (py::isinstance<py::int_>(o) || py::isinstance<py::float_>(o) ||
                                      py::hasattr(o, "__index__") || py::hasattr(o, "__float__"));
    switch (port.type) {
        case PortType::Image:
            if (!py::isinstance<Image>(o)) wrongType(port, o, what, "a darkroom.Image");
            return Value(o.cast<const Image&>().buffer);
        case PortType::Float:
            if (!isNumber) wrongType(port, o, what, "a number");
            return Value(o.cast<double>());
        case PortType::Int: {
            if (!isNumber) wrongType(port, o, what, "an integer");
            if (!py::isinstance<py::float_>(o)) return Value(o.cast<std::int64_t>());
            const double d = o.cast<double>();  // 3.0 is 3; 3.5 is no integer
            if (!(d == std::floor(d) && std::fabs(d) < 9.2e18)) wrongType(port, o, what, "an integer");
            return Value(std::int64_t(d));
        }
        case PortType::Bool:
            if (!isBool) wrongType(port, o, what, "True or False");
            return Value(o.cast<bool>());
        case PortType::Color: {
            if (py::isinstance<py::str>(o)) return parseValue(PortType::Color, o.cast<std::string>());
            const auto v = numbers(port, o, what, "[r, g, b] or [r, g, b, a] (linear), or '#rrggbb'");
            if (v.size() != 3 && v.size() != 4) wrongType(port, o, what, "3 or 4 numbers");
            return Value(Color{float(v[0]), float(v[1]), float(v[2]), v.size() == 4 ? float(v[3]) : 1.0f});
        }
        case PortType::Vec3: {
            const auto v = numbers(port, o, what, "[x, y, z]");
            if (v.size() != 3) wrongType(port, o, what, "3 numbers");
            return Value(Vec3{v[0], v[1], v[2]});
        }
        case PortType::Row: return rowValue(port, o, what);
        default:
            if (py::isinstance<py::str>(o)) return Value(o.cast<std::string>());
            if (py::hasattr(o, "__fspath__")) return Value(py::str(o.attr("__fspath__")()).cast<std::string>());
            wrongType(port, o, what, "a str");
    }
}

py::object fromValue(PortType type, const Value& v) {
    if (v.empty()) return py::none();
    switch (type) {
        case PortType::Image: return py::cast(Image{v.asImage()});
        case PortType::Float: return py::float_(v.asFloat());
        case PortType::Int: return py::int_(v.asInt());
        case PortType::Bool: return py::bool_(v.asBool());
        case PortType::Color: {
            const Color c = v.asColor();
            return py::make_tuple(c.r, c.g, c.b, c.a);
        }
        case PortType::Vec3: {
            const Vec3 p = v.asVec3();
            return py::make_tuple(p.x, p.y, p.z);
        }
        case PortType::Row: {
            py::dict d;
            for (const auto& [column, text] : v.asRow().cells()) d[py::str(column)] = text;
            return d;
        }
        default: return py::str(v.asString());
    }
}

}  // namespace darkroom::python
