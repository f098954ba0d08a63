#pragma once
#include <darkroom/buffer.h>
#include <darkroom/export.h>
#include <darkroom/math.h>
#include <darkroom/row.h>

#include <cstdint>
#include <string>
#include <variant>

namespace darkroom {

// Every port has one of these types. Value ports (everything but Image) have a
// default and a widget while unconnected, and can be driven by another node.
enum class PortType : std::uint8_t {
    Image,
    Float,
    Int,
    Bool,
    Enum,      // one of PortSpec::choices, stored as its string
    Color,     // linear RGBA
    ColorMap,  // a preset name ("viridis") or a path to a ParaView colour-map JSON
    Vec3,
    String,
    Path,  // a file path read, resolved relative to the pipeline file
    // A file or folder the node writes, resolved against the runner's
    // --output folder (else the pipeline's), and never over what a node
    // upstream read. Batch shading renames it per entry.
    OutputPath,
    // One entry of a table (row.h): what a database reader says it read and
    // what a database writer files its product under.
    Row,
};

DARKROOM_API const char* toString(PortType t);
// Returns false for an unknown name.
DARKROOM_API bool parsePortType(std::string_view name, PortType& out);

struct Color {
    float r = 0, g = 0, b = 0, a = 1;
    bool operator==(const Color&) const = default;
};

// The value flowing through a port. Enum, ColorMap, String, Path and
// OutputPath all hold a std::string; the port's type says how to interpret it.
class DARKROOM_API Value {
public:
    using Storage = std::variant<std::monostate, bool, std::int64_t, double, std::string, Color,
                                 Vec3, BufferPtr, Row>;

    Value() = default;
    Value(bool b) : v_(b) {}
    Value(int i) : v_(std::int64_t(i)) {}
    Value(std::int64_t i) : v_(i) {}
    Value(double d) : v_(d) {}
    Value(const char* s) : v_(std::string(s)) {}
    Value(std::string s) : v_(std::move(s)) {}
    Value(Color c) : v_(c) {}
    Value(Vec3 v) : v_(v) {}
    Value(BufferPtr b) : v_(std::move(b)) {}
    Value(Row r) : v_(std::move(r)) {}

    bool empty() const { return std::holds_alternative<std::monostate>(v_); }
    const Storage& storage() const { return v_; }

    // Typed access; numeric types convert between each other, anything else
    // mismatched throws darkroom::Error.
    bool asBool() const;
    std::int64_t asInt() const;
    double asFloat() const;
    const std::string& asString() const;
    Color asColor() const;
    Vec3 asVec3() const;
    const BufferPtr& asImage() const;
    const Row& asRow() const;

    bool operator==(const Value& o) const;

private:
    Storage v_;
};

// Text form used by pipeline files and `--set`: numbers in shortest round-trip
// form, bools as true/false, colours and vectors as "[r, g, b, a]" / "[x, y, z]",
// rows as "time=0.5, phi=30" (row.h).
DARKROOM_API std::string formatValue(PortType type, const Value& v);
// Parses text into a value of `type`; throws darkroom::Error saying what was expected.
DARKROOM_API Value parseValue(PortType type, std::string_view text);

}  // namespace darkroom
