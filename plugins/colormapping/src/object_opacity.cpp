#include "object_opacity.h"

#include <darkroom/error.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>

namespace darkroom::colormapping {

namespace {

std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t\n");
    if (b == std::string::npos) return {};
    return s.substr(b, s.find_last_not_of(" \t\n") - b + 1);
}

std::pair<std::uint32_t, float> parsePair(const std::string& pair) {
    const std::string bad = "objectOpacity: '" + pair + "' is not 'id: opacity' (e.g. \"0: 0.3, 2: 1\")";
    const auto colon = pair.find(':');
    if (colon == std::string::npos) throw Error(bad);
    const std::string id = trim(pair.substr(0, colon)), value = trim(pair.substr(colon + 1));
    if (id.empty() || value.empty() || id.find_first_not_of("0123456789") != std::string::npos) throw Error(bad);
    errno = 0;
    char* end = nullptr;
    const unsigned long long n = std::strtoull(id.c_str(), &end, 10);
    if (errno != 0 || n >= 0xFFFFFFFFull) throw Error(bad + "; the id is out of range");
    const float a = std::strtof(value.c_str(), &end);
    if (*end != '\0') throw Error(bad);
    if (!(a >= 0.0f && a <= 1.0f)) throw Error("objectOpacity: the opacity of object " + id + " is " + value +
                                               "; it must lie in [0, 1]");
    return {std::uint32_t(n), a};
}

}  // namespace

ObjectOpacity ObjectOpacity::parse(const std::string& text) {
    ObjectOpacity o;
    std::string item;
    for (std::size_t i = 0; i <= text.size(); ++i) {
        if (i < text.size() && text[i] != ',' && text[i] != ';') {
            item += text[i];
            continue;
        }
        if (!trim(item).empty()) o.byId_.push_back(parsePair(trim(item)));
        item.clear();
    }
    std::sort(o.byId_.begin(), o.byId_.end());
    for (std::size_t k = 1; k < o.byId_.size(); ++k)
        if (o.byId_[k].first == o.byId_[k - 1].first)
            throw Error("objectOpacity: object " + std::to_string(o.byId_[k].first) + " is listed twice");
    return o;
}

float ObjectOpacity::operator()(std::uint32_t id) const {
    const auto it = std::lower_bound(byId_.begin(), byId_.end(), std::make_pair(id, 0.0f),
                                     [](const auto& a, const auto& b) { return a.first < b.first; });
    return it != byId_.end() && it->first == id ? it->second : 1.0f;
}

bool ObjectOpacity::allOpaque() const {
    return std::all_of(byId_.begin(), byId_.end(), [](const auto& p) { return p.second >= 1.0f; });
}

}  // namespace darkroom::colormapping
