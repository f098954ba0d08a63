#pragma once
#include <darkroom/error.h>
#include <darkroom/export.h>
#include <darkroom/value.h>

#include <initializer_list>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace darkroom {

// A typed, named, documented input or output. Every parameter is an input
// port: unconnected it shows `defaultValue` (or the pipeline's value) in a
// widget; connected it takes the upstream node's output.
struct PortSpec {
    std::string name;
    PortType type = PortType::Float;
    std::string doc;
    Value defaultValue;
    std::optional<double> minimum;  // numeric ports: allowed range, enforced on set
    std::optional<double> maximum;
    std::vector<std::string> choices;   // Enum ports; ColorMap ports list presets here
    std::vector<std::string> channels;  // Image ports: channels needed (in) / produced (out)
    bool optional = false;              // Image inputs: may stay unconnected
    bool multiple = false;              // Image inputs: any number of connections, in edge order

    bool isImage() const { return type == PortType::Image; }
};

struct PortHandle;

// What a filter declares. Usually made from the filter's typed port handles
// (below): `PortList ports() const override { return {image, amount, result}; }`.
// The builder functions do the same one port at a time, e.g.
//   PortList p;
//   p.imageIn("image", "Input colour", {"R", "G", "B"});
//   p.floatIn("strength", 1.0, 0.0, 10.0, "How much to darken");
//   p.imageOut("image", "Result");
// A returned reference stays valid until the next port is added.
struct DARKROOM_API PortList {
    std::vector<PortSpec> inputs;
    std::vector<PortSpec> outputs;

    PortList() = default;
    // Inputs and outputs in the order given; throws on a name declared twice.
    PortList(std::initializer_list<std::reference_wrapper<const PortHandle>> handles);

    const PortSpec* input(std::string_view name) const;
    const PortSpec* output(std::string_view name) const;

    PortSpec& imageIn(std::string name, std::string doc, std::vector<std::string> channels = {});
    PortSpec& optionalImageIn(std::string name, std::string doc,
                              std::vector<std::string> channels = {});
    PortSpec& imagesIn(std::string name, std::string doc);
    PortSpec& floatIn(std::string name, double def, double min, double max, std::string doc);
    PortSpec& intIn(std::string name, std::int64_t def, std::int64_t min, std::int64_t max,
                    std::string doc);
    PortSpec& boolIn(std::string name, bool def, std::string doc);
    PortSpec& enumIn(std::string name, std::vector<std::string> choices, std::string def,
                     std::string doc);
    PortSpec& colorIn(std::string name, Color def, std::string doc);
    PortSpec& colorMapIn(std::string name, std::string def, std::string doc);
    PortSpec& vec3In(std::string name, Vec3 def, std::string doc);
    PortSpec& stringIn(std::string name, std::string def, std::string doc);
    PortSpec& pathIn(std::string name, std::string def, std::string doc);
    PortSpec& outputPathIn(std::string name, std::string def, std::string doc);
    PortSpec& rowIn(std::string name, std::string doc);

    PortSpec& imageOut(std::string name, std::string doc, std::vector<std::string> channels = {});
    PortSpec& valueOut(std::string name, PortType type, std::string doc);
};

// Checks a value against a port's range/choices; throws darkroom::Error naming
// the port, the value and what is allowed.
DARKROOM_API void checkValue(const PortSpec& port, const Value& v);

// Checks a whole declaration: unique names, defaults inside their ranges,
// enum defaults among the choices. The host runs it when a plugin registers,
// so a misspelt choice fails there, naming the filter and the port.
DARKROOM_API void checkPorts(const PortList& ports);

// ---------------------------------------------------------------------------
// Typed port handles. A filter declares each port once, as a member, and uses
// the member in execute(): no port-name strings are repeated, enum ports read
// as C++ enums, and ctx.get(handle) returns the port's C++ type.
//
//   darkroom::ImageIn image{"image", "Linear RGBA colour", {"R", "G", "B"}};
//   darkroom::FloatIn amount{"amount", 1.0, 0.0, 1.0, "0 keeps the input, 1 inverts fully"};
//   darkroom::ImageOut result{"image", "Inverted colour"};
//   darkroom::PortList ports() const override { return {image, amount, result}; }
//   void execute(darkroom::Context& ctx) override { BufferPtr in = ctx.get(image); ... }
// ---------------------------------------------------------------------------
struct PortHandle {
    PortSpec spec;
    bool output = false;
    const std::string& name() const { return spec.name; }

protected:
    PortHandle(std::string name, PortType type, std::string doc, bool isOutput = false) : output(isOutput) {
        spec.name = std::move(name);
        spec.type = type;
        spec.doc = std::move(doc);
    }
};

// A required image input (Context::get throws, naming the port, when unconnected).
struct ImageIn : PortHandle {
    ImageIn(std::string name, std::string doc, std::vector<std::string> channels = {})
        : PortHandle(std::move(name), PortType::Image, std::move(doc)) {
        spec.channels = std::move(channels);
    }
};
// An image input that may stay unconnected (Context::get returns nullptr).
struct OptionalImageIn : PortHandle {
    OptionalImageIn(std::string name, std::string doc, std::vector<std::string> channels = {})
        : PortHandle(std::move(name), PortType::Image, std::move(doc)) {
        spec.channels = std::move(channels);
        spec.optional = true;
    }
};
// Any number of images, in edge order.
struct ImagesIn : PortHandle {
    ImagesIn(std::string name, std::string doc) : PortHandle(std::move(name), PortType::Image, std::move(doc)) {
        spec.multiple = true;
    }
};
struct FloatIn : PortHandle {
    FloatIn(std::string name, double def, double min, double max, std::string doc)
        : PortHandle(std::move(name), PortType::Float, std::move(doc)) {
        spec.defaultValue = def;
        spec.minimum = min;
        spec.maximum = max;
    }
};
struct IntIn : PortHandle {
    IntIn(std::string name, std::int64_t def, std::int64_t min, std::int64_t max, std::string doc)
        : PortHandle(std::move(name), PortType::Int, std::move(doc)) {
        spec.defaultValue = def;
        spec.minimum = double(min);
        spec.maximum = double(max);
    }
};
struct BoolIn : PortHandle {
    BoolIn(std::string name, bool def, std::string doc) : PortHandle(std::move(name), PortType::Bool, std::move(doc)) {
        spec.defaultValue = def;
    }
};
struct ColorIn : PortHandle {
    ColorIn(std::string name, Color def, std::string doc)
        : PortHandle(std::move(name), PortType::Color, std::move(doc)) {
        spec.defaultValue = def;
    }
};
// A preset name or a ParaView colour-map JSON path (presets listed as choices).
struct DARKROOM_API ColorMapIn : PortHandle {
    ColorMapIn(std::string name, std::string def, std::string doc);
};
struct Vec3In : PortHandle {
    Vec3In(std::string name, Vec3 def, std::string doc) : PortHandle(std::move(name), PortType::Vec3, std::move(doc)) {
        spec.defaultValue = def;
    }
};
struct StringIn : PortHandle {
    StringIn(std::string name, std::string def, std::string doc)
        : PortHandle(std::move(name), PortType::String, std::move(doc)) {
        spec.defaultValue = std::move(def);
    }
};
// A file path, resolved relative to the pipeline file (Context::get resolves it).
struct PathIn : PortHandle {
    PathIn(std::string name, std::string def, std::string doc)
        : PortHandle(std::move(name), PortType::Path, std::move(doc)) {
        spec.defaultValue = std::move(def);
    }
};
// A file or folder the node writes. Context::get resolves it against the
// runner's --output folder (else the pipeline's) and refuses a path over what
// a node upstream read; the batch workflow renames it per entry. Every writer
// declares its output this way, so hosts find outputs by kind, not by name.
struct OutputPathIn : PortHandle {
    OutputPathIn(std::string name, std::string def, std::string doc)
        : PortHandle(std::move(name), PortType::OutputPath, std::move(doc)) {
        spec.defaultValue = std::move(def);
    }
};
// The entry being shaded (row.h): connected to a database reader's row
// output, or typed as "phi=30, theta=45"; empty by default. A node with a
// connected row input and an OutputPath is a database writer to the batch
// workflow, which then leaves its path alone (the node names its entries).
struct RowIn : PortHandle {
    RowIn(std::string name, std::string doc) : PortHandle(std::move(name), PortType::Row, std::move(doc)) {
        spec.defaultValue = Row();
    }
};
// One of a fixed set of choices, read as the enum E:
//   enum class Method { Hemisphere, Horizon };
//   EnumIn<Method> method{"method", {{Method::Hemisphere, "hemisphere"}, {Method::Horizon, "horizon"}},
//                         Method::Horizon, "How occlusion is estimated"};
template <class E>
struct EnumIn : PortHandle {
    std::vector<std::pair<E, std::string>> mapping;
    EnumIn(std::string name, std::vector<std::pair<E, std::string>> choices, E def, std::string doc)
        : PortHandle(std::move(name), PortType::Enum, std::move(doc)), mapping(std::move(choices)) {
        for (const auto& [value, text] : mapping) {
            spec.choices.push_back(text);
            if (value == def) spec.defaultValue = text;
        }
        // An empty default fails checkPorts() at registration, naming the port.
    }
    // The enum value of a choice. The host checks values against the choices
    // before execute() runs, so this throws only on a host bug.
    E parse(const std::string& text) const {
        for (const auto& [value, t] : mapping)
            if (t == text) return value;
        throw Error("port '" + spec.name + "': '" + text + "' is not one of its choices");
    }
};
struct ImageOut : PortHandle {
    ImageOut(std::string name, std::string doc, std::vector<std::string> channels = {})
        : PortHandle(std::move(name), PortType::Image, std::move(doc), true) {
        spec.channels = std::move(channels);
    }
};
// A value output (e.g. a range a later node displays), of any value type.
struct ValueOut : PortHandle {
    ValueOut(std::string name, PortType type, std::string doc) : PortHandle(std::move(name), type, std::move(doc), true) {}
};

}  // namespace darkroom
