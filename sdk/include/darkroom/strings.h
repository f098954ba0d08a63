#pragma once
// The small text helpers every part of Darkroom needs, in one place:
// trimming, splitting, joining. Header-only (inline), so they add nothing to
// the SDK's ABI and a plugin uses them without linking anything more.
#include <string>
#include <string_view>
#include <vector>

namespace darkroom {

// Without leading and trailing spaces and tabs (what separates the fields
// of data.csv, a --where list, a pipeline's edge).
inline std::string_view trimBlanks(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
}

// Without leading and trailing ASCII white space (space, \t, \n, \v, \f, \r):
// for values typed by hand, which may end in a line break.
inline std::string_view trimSpace(std::string_view s) {
    const auto space = [](char c) { return c == ' ' || (c >= '\t' && c <= '\r'); };
    while (!s.empty() && space(s.front())) s.remove_prefix(1);
    while (!s.empty() && space(s.back())) s.remove_suffix(1);
    return s;
}

// The parts of `s` between the separators, empty parts included ("a,,b"
// gives "a", "", "b"; "" gives one empty part).
inline std::vector<std::string_view> split(std::string_view s, char separator) {
    std::vector<std::string_view> parts;
    for (std::size_t start = 0;;) {
        const std::size_t end = s.find(separator, start);
        parts.push_back(s.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
        if (end == std::string_view::npos) return parts;
        start = end + 1;
    }
}

// Names separated by commas, spaces or tabs, empty ones dropped: a channel
// list as typed ("R, G, B", "R G B", "R,G,B" give R, G, B).
inline std::vector<std::string> splitNames(std::string_view s) {
    std::vector<std::string> names;
    std::string name;
    for (const char c : s) {
        if (c == ',' || c == ' ' || c == '\t') {
            if (!name.empty()) names.push_back(std::move(name));
            name.clear();
        } else {
            name += c;
        }
    }
    if (!name.empty()) names.push_back(std::move(name));
    return names;
}

// Comma-separated items, trimmed of spaces and tabs, empty ones dropped;
// an item may hold spaces ("time, phi angle" gives time, phi angle): a list
// of column or scalar names.
inline std::vector<std::string> splitList(std::string_view s) {
    std::vector<std::string> items;
    for (const std::string_view part : split(s, ','))
        if (const std::string_view item = trimBlanks(part); !item.empty()) items.emplace_back(item);
    return items;
}

// The parts with `separator` between them.
template <class Parts>
std::string join(const Parts& parts, std::string_view separator) {
    std::string out;
    bool first = true;
    for (const auto& p : parts) {
        if (!first) out += separator;
        out += p;
        first = false;
    }
    return out;
}

}  // namespace darkroom
