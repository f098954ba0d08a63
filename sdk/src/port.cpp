#include <darkroom/colormap.h>
#include <darkroom/error.h>
#include <darkroom/port.h>

#include <algorithm>
#include <cmath>

namespace darkroom {

namespace {
PortSpec& add(std::vector<PortSpec>& v, std::string name, PortType t, std::string doc) {
    for (const auto& p : v)
        if (p.name == name) throw Error("port '" + name + "' is declared twice");
    PortSpec p;
    p.name = std::move(name);
    p.type = t;
    p.doc = std::move(doc);
    v.push_back(std::move(p));
    return v.back();
}
const PortSpec* find(const std::vector<PortSpec>& v, std::string_view n) {
    for (const auto& p : v)
        if (p.name == n) return &p;
    return nullptr;
}
}  // namespace

PortList::PortList(std::initializer_list<std::reference_wrapper<const PortHandle>> handles) {
    for (const PortHandle& h : handles) {
        std::vector<PortSpec>& v = h.output ? outputs : inputs;
        if (find(v, h.spec.name))
            throw Error(std::string(h.output ? "output" : "input") + " port '" + h.spec.name + "' is declared twice");
        v.push_back(h.spec);
    }
}

ColorMapIn::ColorMapIn(std::string name, std::string def, std::string doc)
    : PortHandle(std::move(name), PortType::ColorMap, std::move(doc)) {
    spec.defaultValue = std::move(def);
    spec.choices = colorMapPresets();
}

const PortSpec* PortList::input(std::string_view n) const { return find(inputs, n); }
const PortSpec* PortList::output(std::string_view n) const { return find(outputs, n); }

PortSpec& PortList::imageIn(std::string name, std::string doc, std::vector<std::string> channels) {
    PortSpec& p = add(inputs, std::move(name), PortType::Image, std::move(doc));
    p.channels = std::move(channels);
    return p;
}
PortSpec& PortList::optionalImageIn(std::string name, std::string doc, std::vector<std::string> channels) {
    PortSpec& p = imageIn(std::move(name), std::move(doc), std::move(channels));
    p.optional = true;
    return p;
}
PortSpec& PortList::imagesIn(std::string name, std::string doc) {
    PortSpec& p = add(inputs, std::move(name), PortType::Image, std::move(doc));
    p.multiple = true;
    return p;
}
PortSpec& PortList::floatIn(std::string name, double def, double min, double max, std::string doc) {
    PortSpec& p = add(inputs, std::move(name), PortType::Float, std::move(doc));
    p.defaultValue = def;
    p.minimum = min;
    p.maximum = max;
    return p;
}
PortSpec& PortList::intIn(std::string name, std::int64_t def, std::int64_t min, std::int64_t max,
                          std::string doc) {
    PortSpec& p = add(inputs, std::move(name), PortType::Int, std::move(doc));
    p.defaultValue = def;
    p.minimum = double(min);
    p.maximum = double(max);
    return p;
}
PortSpec& PortList::boolIn(std::string name, bool def, std::string doc) {
    PortSpec& p = add(inputs, std::move(name), PortType::Bool, std::move(doc));
    p.defaultValue = def;
    return p;
}
PortSpec& PortList::enumIn(std::string name, std::vector<std::string> choices, std::string def,
                           std::string doc) {
    PortSpec& p = add(inputs, std::move(name), PortType::Enum, std::move(doc));
    p.choices = std::move(choices);
    p.defaultValue = std::move(def);
    return p;
}
PortSpec& PortList::colorIn(std::string name, Color def, std::string doc) {
    PortSpec& p = add(inputs, std::move(name), PortType::Color, std::move(doc));
    p.defaultValue = def;
    return p;
}
PortSpec& PortList::colorMapIn(std::string name, std::string def, std::string doc) {
    PortSpec& p = add(inputs, std::move(name), PortType::ColorMap, std::move(doc));
    p.defaultValue = std::move(def);
    p.choices = colorMapPresets();
    return p;
}
PortSpec& PortList::vec3In(std::string name, Vec3 def, std::string doc) {
    PortSpec& p = add(inputs, std::move(name), PortType::Vec3, std::move(doc));
    p.defaultValue = def;
    return p;
}
PortSpec& PortList::stringIn(std::string name, std::string def, std::string doc) {
    PortSpec& p = add(inputs, std::move(name), PortType::String, std::move(doc));
    p.defaultValue = std::move(def);
    return p;
}
PortSpec& PortList::pathIn(std::string name, std::string def, std::string doc) {
    PortSpec& p = add(inputs, std::move(name), PortType::Path, std::move(doc));
    p.defaultValue = std::move(def);
    return p;
}
PortSpec& PortList::outputPathIn(std::string name, std::string def, std::string doc) {
    PortSpec& p = add(inputs, std::move(name), PortType::OutputPath, std::move(doc));
    p.defaultValue = std::move(def);
    return p;
}
PortSpec& PortList::rowIn(std::string name, std::string doc) {
    PortSpec& p = add(inputs, std::move(name), PortType::Row, std::move(doc));
    p.defaultValue = Row();
    return p;
}
PortSpec& PortList::imageOut(std::string name, std::string doc, std::vector<std::string> channels) {
    PortSpec& p = add(outputs, std::move(name), PortType::Image, std::move(doc));
    p.channels = std::move(channels);
    return p;
}
PortSpec& PortList::valueOut(std::string name, PortType type, std::string doc) {
    return add(outputs, std::move(name), type, std::move(doc));
}

void checkValue(const PortSpec& port, const Value& v) {
    auto fail = [&](const std::string& why) {
        throw Error("port '" + port.name + "': " + why);
    };
    try {
        switch (port.type) {
            case PortType::Float:
            case PortType::Int: {
                const double d = port.type == PortType::Int ? double(v.asInt()) : v.asFloat();
                if (port.type == PortType::Int && std::get_if<double>(&v.storage()))
                    fail("expected an integer, got " + formatValue(PortType::Float, v));
                if (std::isnan(d)) break;
                if ((port.minimum && d < *port.minimum) || (port.maximum && d > *port.maximum))
                    fail("value " + formatValue(port.type, v) + " is outside the allowed range [" +
                         (port.minimum ? formatValue(PortType::Float, *port.minimum) : std::string("-inf")) + ", " +
                         (port.maximum ? formatValue(PortType::Float, *port.maximum) : std::string("inf")) + "]");
                break;
            }
            case PortType::Bool: (void)v.asBool(); break;
            case PortType::Enum: {
                const std::string& s = v.asString();
                if (std::find(port.choices.begin(), port.choices.end(), s) == port.choices.end()) {
                    std::string all;
                    for (const auto& c : port.choices) all += (all.empty() ? "" : ", ") + c;
                    fail("'" + s + "' is not one of: " + all);
                }
                break;
            }
            case PortType::Color: (void)v.asColor(); break;
            case PortType::Vec3: (void)v.asVec3(); break;
            case PortType::Image: (void)v.asImage(); break;
            case PortType::Row: (void)v.asRow(); break;
            default: (void)v.asString(); break;
        }
    } catch (const Error& e) {
        const std::string m = e.what();
        if (m.rfind("port '", 0) == 0) throw;
        fail(m);
    }
}

void checkPorts(const PortList& ports) {
    for (const auto* list : {&ports.inputs, &ports.outputs}) {
        const char* kind = list == &ports.inputs ? "input" : "output";
        for (std::size_t i = 0; i < list->size(); ++i) {
            const PortSpec& p = (*list)[i];
            if (p.name.empty()) throw Error(std::string("an ") + kind + " port has no name");
            for (std::size_t k = 0; k < i; ++k)
                if ((*list)[k].name == p.name)
                    throw Error(std::string(kind) + " port '" + p.name + "' is declared twice");
            if (list == &ports.outputs || p.type == PortType::Image) continue;
            if (p.type == PortType::Enum && p.choices.empty())
                throw Error("enum port '" + p.name + "' has no choices");
            if (p.minimum && p.maximum && *p.minimum > *p.maximum)
                throw Error("port '" + p.name + "': minimum is above maximum");
            // The default must be a value the port accepts (an enum default
            // that is not among the choices is a misspelling).
            if (p.type == PortType::ColorMap) {
                (void)p.defaultValue.asString();
                continue;
            }
            if (p.defaultValue.empty()) throw Error("port '" + p.name + "' has no default value");
            checkValue(p, p.defaultValue);
        }
    }
}

}  // namespace darkroom
