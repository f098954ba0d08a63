#include <darkroom/core/path_overlap.h>

#include <filesystem>

namespace darkroom {

namespace fs = std::filesystem;

std::string absoluteNormal(const std::string& path) {
    std::error_code ec;
    fs::path p = fs::absolute(fs::path(path), ec);
    if (ec) p = fs::path(path);
    std::string s = p.lexically_normal().string();
    while (s.size() > 1 && s.back() == '/') s.pop_back();
    return s;
}

namespace {

// Whether `inner` is `outer` or a path below it, component-wise (so that
// "a.cdb2" is not taken to lie inside "a.cdb").
bool within(const std::string& inner, const std::string& outer) {
    if (inner.size() < outer.size() || inner.compare(0, outer.size(), outer) != 0) return false;
    return inner.size() == outer.size() || outer == "/" || inner[outer.size()] == '/';
}

}  // namespace

bool pathsOverlap(const std::string& output, const std::string& input) {
    if (output.empty() || input.empty()) return false;
    const std::string o = absoluteNormal(output), i = absoluteNormal(input);
    return within(o, i) || within(i, o);
}

std::string overlapWording(const std::string& output, const std::string& input) {
    const std::string o = absoluteNormal(output), i = absoluteNormal(input);
    if (o == i) return "is";
    return within(i, o) ? "holds" : "lies inside";
}

}  // namespace darkroom
