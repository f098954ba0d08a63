#pragma once
// Reads a generator's text parameters with range checks. Every accessor
// marks its key as known, so finish() can reject misspelled keys by name.
#include <darkroom/math.h>

#include <map>
#include <set>
#include <string>
#include <vector>

namespace darkroom::generators {

class GeneratorParams {
public:
    GeneratorParams(std::string generator, const std::map<std::string, std::string>& params,
                    bool vertexNormals = false);

    // Whether surfaces that know their exact normals (the isosurface: the
    // field's gradient) should carry them as vertex normals (vertex_normals.h).
    bool vertexNormals() const { return vertexNormals_; }

    bool has(const std::string& key) const;
    double number(const std::string& key, double fallback, double lo, double hi);
    int integer(const std::string& key, int fallback, int lo, int hi);
    Vec3 vec3(const std::string& key, const Vec3& fallback);
    std::string choice(const std::string& key, const std::string& fallback,
                       const std::vector<std::string>& options);

    // Throws for any key no accessor asked for, listing the accepted ones.
    void finish() const;

    // "generator 'NAME': parameter 'KEY' " + what, as a darkroom::Error.
    [[noreturn]] void fail(const std::string& key, const std::string& what) const;

private:
    const std::string* find(const std::string& key);

    std::string generator_;
    const std::map<std::string, std::string>& params_;
    std::set<std::string> known_;
    bool vertexNormals_ = false;
};

}  // namespace darkroom::generators
