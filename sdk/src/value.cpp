#include <darkroom/error.h>
#include <darkroom/value.h>
#include <darkroom/strings.h>

#include <charconv>
#include <cmath>
#include <limits>
#include <vector>

namespace darkroom {

namespace {
const char* const kTypeNames[] = {"image", "float", "int",    "bool",   "enum",
                                  "color", "colormap", "vec3", "string", "path", "outpath", "row"};

const char* heldName(const Value::Storage& s) {
    switch (s.index()) {
        case 0: return "nothing";
        case 1: return "a bool";
        case 2: return "an int";
        case 3: return "a float";
        case 4: return "a string";
        case 5: return "a colour";
        case 6: return "a vec3";
        case 7: return "an image";
        default: return "a row";
    }
}

[[noreturn]] void mismatch(const Value::Storage& s, const char* wanted) {
    throw Error(std::string("expected ") + wanted + " but the value is " + heldName(s));
}

std::string formatDouble(double d) {
    if (std::isnan(d)) return "nan";
    if (std::isinf(d)) return d > 0 ? "inf" : "-inf";
    char buf[64];
    auto r = std::to_chars(buf, buf + sizeof buf, d);
    std::string s(buf, r.ptr);
    // Keep floats recognisable as floats in YAML ("1" would read back as an int).
    if (s.find_first_of(".eE") == std::string::npos) s += ".0";
    return s;
}

// Colours are float32: print the shortest text that reads back as the same float.
std::string formatFloat(float f) {
    if (!std::isfinite(f)) return formatDouble(f);
    char buf[64];
    auto r = std::to_chars(buf, buf + sizeof buf, f);
    std::string s(buf, r.ptr);
    if (s.find_first_of(".eE") == std::string::npos) s += ".0";
    return s;
}

bool parseDouble(std::string_view t, double& out) {
    const std::string s = std::string(trimSpace(t));
    if (s == "nan" || s == "NaN" || s == "NAN" || s == ".nan" || s == ".NaN") {
        out = std::numeric_limits<double>::quiet_NaN();
        return true;
    }
    if (s == "inf" || s == "+inf" || s == ".inf" || s == "Infinity") {
        out = std::numeric_limits<double>::infinity();
        return true;
    }
    if (s == "-inf" || s == "-.inf" || s == "-Infinity") {
        out = -std::numeric_limits<double>::infinity();
        return true;
    }
    const char* b = s.data();
    if (!s.empty() && s[0] == '+') ++b;
    auto r = std::from_chars(b, s.data() + s.size(), out);
    return r.ec == std::errc() && r.ptr == s.data() + s.size() && !s.empty();
}

// "[a, b, c]" or "a, b, c" or "a b c" -> numbers.
bool parseList(std::string_view text, std::vector<double>& out) {
    std::string s = std::string(trimSpace(text));
    if (!s.empty() && s.front() == '[') {
        if (s.back() != ']') return false;
        s = s.substr(1, s.size() - 2);
    }
    out.clear();
    std::size_t i = 0;
    while (i <= s.size()) {
        std::size_t j = s.find_first_of(", ", i);
        if (j == std::string::npos) j = s.size();
        const std::string tok = std::string(trimSpace(std::string_view(s).substr(i, j - i)));
        if (!tok.empty()) {
            double d;
            if (!parseDouble(tok, d)) return false;
            out.push_back(d);
        }
        i = j + 1;
    }
    return true;
}

float srgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}
}  // namespace

const char* toString(PortType t) { return kTypeNames[static_cast<int>(t)]; }

bool parsePortType(std::string_view name, PortType& out) {
    for (int i = 0; i < int(std::size(kTypeNames)); ++i)
        if (name == kTypeNames[i]) {
            out = static_cast<PortType>(i);
            return true;
        }
    return false;
}

bool Value::asBool() const {
    if (auto p = std::get_if<bool>(&v_)) return *p;
    if (auto p = std::get_if<std::int64_t>(&v_)) return *p != 0;
    mismatch(v_, "a bool");
}

std::int64_t Value::asInt() const {
    if (auto p = std::get_if<std::int64_t>(&v_)) return *p;
    if (auto p = std::get_if<double>(&v_)) return static_cast<std::int64_t>(std::llround(*p));
    if (auto p = std::get_if<bool>(&v_)) return *p ? 1 : 0;
    mismatch(v_, "an int");
}

double Value::asFloat() const {
    if (auto p = std::get_if<double>(&v_)) return *p;
    if (auto p = std::get_if<std::int64_t>(&v_)) return static_cast<double>(*p);
    mismatch(v_, "a float");
}

const std::string& Value::asString() const {
    if (auto p = std::get_if<std::string>(&v_)) return *p;
    mismatch(v_, "a string");
}

Color Value::asColor() const {
    if (auto p = std::get_if<Color>(&v_)) return *p;
    mismatch(v_, "a colour");
}

Vec3 Value::asVec3() const {
    if (auto p = std::get_if<Vec3>(&v_)) return *p;
    mismatch(v_, "a vec3");
}

const BufferPtr& Value::asImage() const {
    if (auto p = std::get_if<BufferPtr>(&v_)) return *p;
    mismatch(v_, "an image");
}

const Row& Value::asRow() const {
    if (auto p = std::get_if<Row>(&v_)) return *p;
    mismatch(v_, "a row");
}

bool Value::operator==(const Value& o) const {
    if (v_.index() != o.v_.index()) return false;
    // NaN parameters compare equal so a reloaded pipeline equals the saved one.
    if (auto a = std::get_if<double>(&v_)) {
        const double b = std::get<double>(o.v_);
        return *a == b || (std::isnan(*a) && std::isnan(b));
    }
    return v_ == o.v_;
}

std::string formatValue(PortType type, const Value& v) {
    switch (type) {
        case PortType::Image: return "<image>";
        case PortType::Float: return formatDouble(v.asFloat());
        case PortType::Int: return std::to_string(v.asInt());
        case PortType::Bool: return v.asBool() ? "true" : "false";
        case PortType::Color: {
            const Color c = v.asColor();
            return "[" + formatFloat(c.r) + ", " + formatFloat(c.g) + ", " + formatFloat(c.b) + ", " +
                   formatFloat(c.a) + "]";
        }
        case PortType::Vec3: {
            const Vec3 p = v.asVec3();
            return "[" + formatDouble(p.x) + ", " + formatDouble(p.y) + ", " + formatDouble(p.z) + "]";
        }
        case PortType::Row: return formatRow(v.asRow());
        default: return v.asString();
    }
}

Value parseValue(PortType type, std::string_view text) {
    const std::string t = std::string(trimSpace(text));
    switch (type) {
        case PortType::Image: throw Error("an image cannot be given as text; connect an image output");
        case PortType::Float: {
            double d;
            if (!parseDouble(t, d)) throw Error("expected a number, got '" + t + "'");
            return Value(d);
        }
        case PortType::Int: {
            std::int64_t i;
            const char* b = t.data() + (!t.empty() && t[0] == '+');
            auto r = std::from_chars(b, t.data() + t.size(), i);
            if (t.empty() || r.ec != std::errc() || r.ptr != t.data() + t.size())
                throw Error("expected an integer, got '" + t + "'");
            return Value(i);
        }
        case PortType::Bool: {
            if (t == "true" || t == "True" || t == "yes" || t == "on" || t == "1") return Value(true);
            if (t == "false" || t == "False" || t == "no" || t == "off" || t == "0") return Value(false);
            throw Error("expected true or false, got '" + t + "'");
        }
        case PortType::Color: {
            if (!t.empty() && t[0] == '#' && (t.size() == 7 || t.size() == 9)) {
                // Hex colours are sRGB-encoded as in every colour picker.
                float c[4] = {0, 0, 0, 1};
                for (std::size_t k = 0; k * 2 + 1 < t.size(); ++k) {
                    unsigned v = 0;
                    auto r = std::from_chars(t.data() + 1 + 2 * k, t.data() + 3 + 2 * k, v, 16);
                    if (r.ec != std::errc()) throw Error("expected a colour like #ff8800, got '" + t + "'");
                    c[k] = v / 255.0f;
                }
                return Value(Color{srgbToLinear(c[0]), srgbToLinear(c[1]), srgbToLinear(c[2]), c[3]});
            }
            std::vector<double> n;
            if (!parseList(t, n) || (n.size() != 3 && n.size() != 4))
                throw Error("expected a colour [r, g, b] or [r, g, b, a] (linear, 0..1) or #rrggbb, got '" +
                            t + "'");
            return Value(Color{float(n[0]), float(n[1]), float(n[2]), n.size() == 4 ? float(n[3]) : 1.0f});
        }
        case PortType::Vec3: {
            std::vector<double> n;
            if (!parseList(t, n) || n.size() != 3) throw Error("expected a vector [x, y, z], got '" + t + "'");
            return Value(Vec3{n[0], n[1], n[2]});
        }
        case PortType::Row: return Value(parseRow(text));
        default: return Value(std::string(text));
    }
}

}  // namespace darkroom
