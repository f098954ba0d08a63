#include "explorer_state.h"

#include <darkroom/error.h>

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace editor {
namespace {

std::string quote(const std::string& s) {
    std::string out = "\"";
    for (unsigned char c : s) {
        if (c == '%' || c == '"' || c == '\\' || c < 0x20) {
            char buf[4];
            std::snprintf(buf, sizeof buf, "%%%02X", c);
            out += buf;
        } else {
            out += char(c);
        }
    }
    return out + "\"";
}

std::string unquote(const std::string& s) {
    std::string out;
    for (std::size_t i = 0; i < s.size(); ++i) {
        int v = 0;
        if (s[i] == '%' && i + 2 < s.size() &&
            std::from_chars(s.data() + i + 1, s.data() + i + 3, v, 16).ptr == s.data() + i + 3) {
            out += char(v);
            i += 2;
        } else {
            out += s[i];
        }
    }
    return out;
}

double number(const std::string& s, const std::string& what) {
    double v = 0;
    const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
    if (r.ec != std::errc() || r.ptr != s.data() + s.size() || !std::isfinite(v))
        throw darkroom::Error("explore: " + what + " '" + s + "' is not a finite number");
    return v;
}

}  // namespace

std::string toYaml(const ExplorerState& s) {
    std::string out = "{brushes: [";
    for (std::size_t i = 0; i < s.brushes.size(); ++i)
        out += (i ? ", [" : "[") + quote(s.brushes[i].axis) + ", " + quote(s.brushes[i].low) + ", " +
               quote(s.brushes[i].high) + "]";
    out += "], sort: " + quote(s.sort) + ", descending: " + (s.descending ? "true" : "false") +
           ", show: " + (s.pipeline ? "pipeline" : "product") + "}";
    return out;
}

ExplorerState parseExplorerState(const std::string& yaml) {
    ExplorerState s;
    YAML::Node root;
    try {
        root = YAML::Load(yaml);
    } catch (const YAML::Exception& e) {
        throw darkroom::Error("explore: malformed YAML: " + e.msg);
    }
    if (!root.IsMap()) throw darkroom::Error("explore: expected a map {brushes: [...], sort: ..., show: ...}");
    try {
        if (const YAML::Node b = root["brushes"]) {
            if (!b.IsSequence()) throw darkroom::Error("explore: 'brushes' must be a list of [axis, low, high]");
            for (const auto& item : b) {
                if (!item.IsSequence() || item.size() != 3)
                    throw darkroom::Error("explore: a brush must be [axis, low, high]");
                s.brushes.push_back({unquote(item[0].Scalar()), unquote(item[1].Scalar()), unquote(item[2].Scalar())});
            }
        }
        if (const YAML::Node v = root["sort"]) s.sort = unquote(v.Scalar());
        if (const YAML::Node v = root["descending"]) s.descending = v.as<bool>();
        if (const YAML::Node v = root["show"]) {
            if (v.Scalar() != "pipeline" && v.Scalar() != "product")
                throw darkroom::Error("explore: 'show' must be product or pipeline, not '" + v.Scalar() + "'");
            s.pipeline = v.Scalar() == "pipeline";
        }
    } catch (const YAML::Exception& e) {
        throw darkroom::Error("explore: " + e.msg);
    }
    return s;
}

std::string explorerText(const darkroom::Node& n) {
    for (const auto& [k, v] : n.extras)
        if (k == kExploreKey) return v;
    return {};
}

void setExplorerText(darkroom::Graph& g, const std::string& node, const std::string& text) {
    g.setExtra(node, kExploreKey, text);
}

ExplorerState captureState(const ExplorerModel& m, bool pipeline) {
    ExplorerState s;
    for (const auto& b : m.brushes()) {
        const ExplorerAxis& a = m.axes()[b.axis];
        if (a.numeric) {
            s.brushes.push_back({a.name, shortestNumber(b.low), shortestNumber(b.high)});
            continue;
        }
        // Text: the categories it covers, by name.
        const long first = std::max(0L, long(std::ceil(b.low - 1e-9)));
        const long last = std::min(long(a.categories.size()) - 1, long(std::floor(b.high + 1e-9)));
        if (first <= last) s.brushes.push_back({a.name, a.categories[std::size_t(first)], a.categories[std::size_t(last)]});
    }
    if (m.sortAxis() >= 0) s.sort = m.axes()[std::size_t(m.sortAxis())].name;
    s.descending = m.descending();
    s.pipeline = pipeline;
    return s;
}

void applyState(ExplorerModel& m, const ExplorerState& s, std::vector<std::string>* problems) {
    std::vector<Brush> brushes;
    for (const auto& b : s.brushes) {
        const int a = m.axisIndex(b.axis);
        if (a < 0) {
            if (problems) problems->push_back("explore: the database has no column '" + b.axis + "'; brush left out");
            continue;
        }
        const ExplorerAxis& axis = m.axes()[std::size_t(a)];
        if (axis.numeric) {
            brushes.push_back({std::size_t(a), number(b.low, "brush end"), number(b.high, "brush end")});
            continue;
        }
        const auto lo = std::find(axis.categories.begin(), axis.categories.end(), b.low);
        const auto hi = std::find(axis.categories.begin(), axis.categories.end(), b.high);
        if (lo == axis.categories.end() || hi == axis.categories.end()) {
            if (problems)
                problems->push_back("explore: column '" + b.axis + "' has no value '" +
                                    (lo == axis.categories.end() ? b.low : b.high) + "'; brush left out");
            continue;
        }
        brushes.push_back({std::size_t(a), double(lo - axis.categories.begin()), double(hi - axis.categories.begin())});
    }
    m.setBrushes(std::move(brushes));
    const int sortAxis = s.sort.empty() ? -1 : m.axisIndex(s.sort);
    if (!s.sort.empty() && sortAxis < 0 && problems)
        problems->push_back("explore: the database has no column '" + s.sort + "' to sort by");
    m.setSort(sortAxis, s.descending);
}

}  // namespace editor
