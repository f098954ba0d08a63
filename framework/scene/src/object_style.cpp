#include "object_style.h"

#include <cmath>
#include <unordered_map>

namespace darkroom::scenefile {
namespace {

SceneObject wireframe(const SceneObject& s) {
    SceneObject o;
    o.name = s.name;
    o.representation = Representation::Lines;
    std::vector<std::uint32_t> source;  // original vertex per new vertex
    std::unordered_map<std::uint64_t, bool> seen;
    const std::size_t tris = s.indices.size() / 3;
    for (std::size_t t = 0; t < tris; ++t) {
        const std::uint32_t cell = s.primitiveCell.empty() ? std::uint32_t(t) : s.primitiveCell[t];
        for (int k = 0; k < 3; ++k) {
            std::uint32_t a = s.indices[3 * t + k], b = s.indices[3 * t + (k + 1) % 3];
            if (a > b) std::swap(a, b);
            if (!seen.emplace(std::uint64_t(a) << 32 | b, true).second) continue;
            // Segments join vertices i and i+1: each edge gets its own pair.
            o.indices.push_back(std::uint32_t(source.size()));
            o.primitiveCell.push_back(cell);
            source.push_back(a);
            source.push_back(b);
        }
    }
    for (std::uint32_t v : source) o.vertices.insert(o.vertices.end(), s.vertices.begin() + 4 * v, s.vertices.begin() + 4 * v + 4);
    for (const auto& f : s.fields) {
        ScalarField g{f.name, f.association, {}};
        if (f.association == ScalarField::Association::Cell) {
            g.values = f.values;  // cells are unchanged; primitiveCell maps edges to them
        } else {
            g.values.reserve(source.size());
            for (std::uint32_t v : source) g.values.push_back(f.values[v]);
        }
        o.fields.push_back(std::move(g));
    }
    return o;
}

}  // namespace

SceneObject restyle(SceneObject o, Representation wanted) {
    if (wanted == Representation::Surface || wanted == o.representation) return o;
    if (wanted == Representation::Lines) {
        // Only triangles change; vertex parts stay spheres.
        return o.representation == Representation::Surface ? wireframe(o) : o;
    }
    o.representation = Representation::Points;
    o.indices.clear();
    o.primitiveCell.clear();
    std::erase_if(o.fields, [](const ScalarField& f) { return f.association == ScalarField::Association::Cell; });
    return o;
}

void setRadius(SceneObject& o, float radius) {
    for (std::size_t i = 3; i < o.vertices.size(); i += 4) o.vertices[i] = radius;
}

void transform(SceneObject& o, const Vec3& scale, const Vec3& translate) {
    const float r = float((std::abs(scale.x) + std::abs(scale.y) + std::abs(scale.z)) / 3.0);
    for (std::size_t i = 0; i + 3 < o.vertices.size(); i += 4) {
        o.vertices[i] = float(o.vertices[i] * scale.x + translate.x);
        o.vertices[i + 1] = float(o.vertices[i + 1] * scale.y + translate.y);
        o.vertices[i + 2] = float(o.vertices[i + 2] * scale.z + translate.z);
        o.vertices[i + 3] *= r;
    }
}

void keepFields(SceneObject& o, const std::vector<std::string>& names) {
    std::vector<ScalarField> kept;
    for (const auto& n : names)
        for (auto& f : o.fields)
            if (f.name == n) kept.push_back(std::move(f));
    o.fields = std::move(kept);
}

}  // namespace darkroom::scenefile
