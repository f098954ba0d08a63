#include "generator_params.h"
#include <darkroom/strings.h>

#include <darkroom/error.h>

#include <charconv>
#include <cmath>
#include <fmt/format.h>
#include <utility>

namespace darkroom::generators {
namespace {

// Whole-string parse: "12abc" and "" are errors, not 12 and 0.
bool parseDouble(const std::string& text, double& out) {
    const std::string t = std::string(trimSpace(text));
    if (t.empty()) return false;
    const char* first = t.data();
    if (*first == '+') ++first;  // from_chars rejects a leading '+', people write it
    const auto [ptr, ec] = std::from_chars(first, t.data() + t.size(), out);
    return ec == std::errc() && ptr == t.data() + t.size() && std::isfinite(out);
}

}  // namespace

GeneratorParams::GeneratorParams(std::string generator, const std::map<std::string, std::string>& params,
                                 bool vertexNormals)
    : generator_(std::move(generator)), params_(params), vertexNormals_(vertexNormals) {}

void GeneratorParams::fail(const std::string& key, const std::string& what) const {
    throw Error(fmt::format("generator '{}': parameter '{}' {}", generator_, key, what));
}

const std::string* GeneratorParams::find(const std::string& key) {
    known_.insert(key);
    const auto it = params_.find(key);
    return it == params_.end() ? nullptr : &it->second;
}

bool GeneratorParams::has(const std::string& key) const { return params_.count(key) != 0; }

double GeneratorParams::number(const std::string& key, double fallback, double lo, double hi) {
    const std::string* text = find(key);
    if (!text) return fallback;
    double v = 0;
    if (!parseDouble(*text, v)) fail(key, fmt::format("must be a number, got '{}'", *text));
    if (v < lo || v > hi) fail(key, fmt::format("must be between {} and {}, got '{}'", lo, hi, *text));
    return v;
}

int GeneratorParams::integer(const std::string& key, int fallback, int lo, int hi) {
    const std::string* text = find(key);
    if (!text) return fallback;
    double v = 0;
    if (!parseDouble(*text, v) || v != std::floor(v))
        fail(key, fmt::format("must be an integer between {} and {}, got '{}'", lo, hi, *text));
    if (v < lo || v > hi)
        fail(key, fmt::format("must be an integer between {} and {}, got '{}'", lo, hi, *text));
    return static_cast<int>(v);
}

Vec3 GeneratorParams::vec3(const std::string& key, const Vec3& fallback) {
    const std::string* text = find(key);
    if (!text) return fallback;
    // Accept "1 2 3", "1, 2, 3" and "[1, 2, 3]": the scene file may hand a
    // YAML sequence over in any of these spellings.
    std::string t = std::string(trimSpace(*text));
    if (t.size() >= 2 && t.front() == '[' && t.back() == ']') t = t.substr(1, t.size() - 2);
    for (char& c : t)
        if (c == ',') c = ' ';
    std::vector<double> parts;
    std::size_t pos = 0;
    while (pos < t.size()) {
        const auto b = t.find_first_not_of(' ', pos);
        if (b == std::string::npos) break;
        auto e = t.find(' ', b);
        if (e == std::string::npos) e = t.size();
        double v = 0;
        if (!parseDouble(t.substr(b, e - b), v)) parts.push_back(NAN), pos = t.size();
        else parts.push_back(v);
        pos = std::max(pos, e);
    }
    if (parts.size() != 3 || !std::isfinite(parts[0]) || !std::isfinite(parts[1]) || !std::isfinite(parts[2]))
        fail(key, fmt::format("must be three numbers like '0 0 1' or '[0, 0, 1]', got '{}'", *text));
    return {parts[0], parts[1], parts[2]};
}

std::string GeneratorParams::choice(const std::string& key, const std::string& fallback,
                                    const std::vector<std::string>& options) {
    const std::string* text = find(key);
    if (!text) return fallback;
    const std::string t = std::string(trimSpace(*text));
    for (const auto& o : options)
        if (o == t) return t;
    fail(key, fmt::format("must be one of {}, got '{}'", fmt::join(options, ", "), *text));
}

void GeneratorParams::finish() const {
    for (const auto& [key, value] : params_) {
        if (known_.count(key)) continue;
        throw Error(fmt::format("generator '{}': unknown parameter '{}' (expected one of: {})", generator_, key,
                                fmt::join(known_, ", ")));
    }
}

}  // namespace darkroom::generators
