#pragma once
#include <darkroom/export.h>
#include <darkroom/value.h>

#include <optional>
#include <string>
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

// What a filter declares. Built with the helpers below, e.g.
//   PortList p;
//   p.imageIn("image", "Input colour", {"R", "G", "B"});
//   p.floatIn("strength", 1.0, 0.0, 10.0, "How much to darken");
//   p.imageOut("image", "Result");
// A returned reference stays valid until the next port is added.
struct DARKROOM_API PortList {
    std::vector<PortSpec> inputs;
    std::vector<PortSpec> outputs;

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

    PortSpec& imageOut(std::string name, std::string doc, std::vector<std::string> channels = {});
    PortSpec& valueOut(std::string name, PortType type, std::string doc);
};

// Checks a value against a port's range/choices; throws darkroom::Error naming
// the port, the value and what is allowed.
DARKROOM_API void checkValue(const PortSpec& port, const Value& v);

}  // namespace darkroom
