// Numbers and cells as data.csv and entry file names spell them.
#include <darkroom/data/cinema/csv.h>
#include <darkroom/data/cinema/naming.h>
#include <darkroom/data/cinema/writer.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>

namespace darkroom {

namespace {

bool equalsIgnoreCase(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        char x = a[i], y = b[i];
        if (x >= 'A' && x <= 'Z') x = char(x - 'A' + 'a');
        if (y >= 'A' && y <= 'Z') y = char(y - 'A' + 'a');
        if (x != y) return false;
    }
    return true;
}

}  // namespace

bool parseCsvNumber(std::string_view text, double& out) {
    bool negative = false;
    std::string_view body = text;
    if (!body.empty() && (body.front() == '+' || body.front() == '-')) {
        negative = body.front() == '-';
        body.remove_prefix(1);
    }
    if (body.empty()) return false;
    // Spelled out so every case of NaN and infinity reads the same on every
    // standard library.
    if (equalsIgnoreCase(body, "nan")) {
        out = std::numeric_limits<double>::quiet_NaN();
        return true;
    }
    if (equalsIgnoreCase(body, "inf") || equalsIgnoreCase(body, "infinity")) {
        out = negative ? -std::numeric_limits<double>::infinity()
                       : std::numeric_limits<double>::infinity();
        return true;
    }
    // from_chars takes no hex in `general` format and no leading '+'; we
    // removed the sign so "+1e3" and "-.5" both read.
    if (!((body.front() >= '0' && body.front() <= '9') || body.front() == '.')) return false;
    double v = 0;
    const auto [ptr, ec] = std::from_chars(body.data(), body.data() + body.size(), v,
                                           std::chars_format::general);
    if (ptr != body.data() + body.size()) return false;
    if (ec == std::errc::result_out_of_range) {
        // Overflow reads as infinity, underflow as zero, like strtod; which
        // one it was is the sign of the exponent (from_chars leaves v alone).
        const std::size_t e = body.find_first_of("eE");
        const bool underflow = e != std::string_view::npos && e + 1 < body.size() && body[e + 1] == '-';
        v = underflow ? 0.0 : std::numeric_limits<double>::infinity();
    } else if (ec != std::errc()) {
        return false;
    }
    out = negative ? -v : v;
    return true;
}

std::string formatCsvNumber(double value) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    if (value == 0) value = 0;  // -0 and 0 are the same sample
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, value);  // shortest round trip
    return std::string(buf, r.ptr);
}

std::string quoteCsvCell(std::string_view text) {
    const bool needs = text.find_first_of(",\"\r\n") != std::string_view::npos ||
                       (!text.empty() && (text.front() == ' ' || text.front() == '\t' ||
                                          text.back() == ' ' || text.back() == '\t'));
    if (!needs) return std::string(text);
    std::string out = "\"";
    for (char c : text) {
        if (c == '"') out += '"';
        out += c;
    }
    out += '"';
    return out;
}

std::string CinemaValue::str() const { return isNumber_ ? formatCsvNumber(number_) : text_; }

std::string cinemaNamePart(std::string_view text, bool startsName) {
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
                        c == '+' || c == '-';
        // A name starting with '-' reads as an option, with '.' as hidden.
        const bool leading = startsName && i == 0 && (c == '-' || c == '.');
        out += ok && !leading ? c : '~';
    }
    return out;
}

std::string cinemaEntryName(const std::vector<std::pair<std::string, std::string>>& parameters) {
    std::string name;
    for (std::size_t i = 0; i < parameters.size(); ++i) {
        if (i) name += '_';
        name += cinemaNamePart(parameters[i].first, i == 0);
        name += '=';
        name += cinemaNamePart(parameters[i].second, false);
    }
    if (name.empty()) return "entry";
    // File systems stop at 255 bytes; keep a readable prefix and make it
    // unique with a hash of the whole name (FNV-1a, stable everywhere).
    constexpr std::size_t kMax = 200;
    if (name.size() > kMax) {
        std::uint64_t h = 1469598103934665603ull;
        for (unsigned char c : name) h = (h ^ c) * 1099511628211ull;
        char hex[17];
        std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
        name = name.substr(0, kMax - 17) + "~" + hex;
    }
    return name;
}

}  // namespace darkroom
