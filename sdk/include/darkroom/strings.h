#pragma once
// The small text helpers every part of Darkroom needs, in one place:
// trimming, splitting, joining, and the "did you mean" of messages.
// Header-only (inline), so they add nothing to the SDK's ABI and a plugin
// uses them without linking anything more.
#include <algorithm>
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

// Edits (insert, delete, replace, swap two neighbours) from a to b: the
// optimal string alignment distance, so "paramters" and "egdes" are 1 away.
inline std::size_t editDistance(std::string_view a, std::string_view b) {
    std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
    for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
    for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i)
        for (std::size_t j = 1; j <= b.size(); ++j) {
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    return d[a.size()][b.size()];
}

// The valid name closest to `name` by edit distance, if it is close enough to
// be a misspelling of it (at most a third of its letters wrong); "" if none.
// The one spelling check of every message that names what was meant: keys of
// pipeline and scene files, node types, nodes, ports, colour-map presets.
inline std::string nearestName(std::string_view name, const std::vector<std::string>& valid) {
    std::string best;
    std::size_t bestDistance = 0;
    // Names are short; anything long is no misspelling of one.
    if (name.size() > 64) return best;
    for (const auto& v : valid) {
        const std::size_t d = editDistance(name, v);
        if (d * 3 > std::max(v.size(), std::size_t(3))) continue;
        if (best.empty() || d < bestDistance) {
            best = v;
            bestDistance = d;
        }
    }
    return best;
}

// " (did you mean 'parameters'?)" when `name` looks like a misspelling of one
// of `valid`, else "": appended to a message that names what is unknown.
inline std::string didYouMean(std::string_view name, const std::vector<std::string>& valid) {
    const std::string near = nearestName(name, valid);
    return near.empty() ? std::string() : " (did you mean '" + near + "'?)";
}

}  // namespace darkroom
