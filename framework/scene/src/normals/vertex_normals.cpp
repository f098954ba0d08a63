// Vertex normals as the point fields N.x, N.y, N.z of a surface object:
// attaching, taking and transforming them, and finding those a file brought.
#include <darkroom/scene/vertex_normals.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace darkroom {
namespace {

const ScalarField* pointField(const SceneObject& o, const std::string& name) {
    for (const auto& f : o.fields)
        if (f.name == name && f.association == ScalarField::Association::Point && f.values.size() == o.vertexCount())
            return &f;
    return nullptr;
}

// Unit vectors from three component fields; a zero, or a component that is
// not finite, gives the zero normal ("none here").
VertexNormals unitNormals(const ScalarField& x, const ScalarField& y, const ScalarField& z) {
    VertexNormals n(3 * x.values.size());
    for (std::size_t i = 0; i < x.values.size(); ++i) {
        const Vec3 v = normalize(Vec3{x.values[i], y.values[i], z.values[i]});
        const bool usable = std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
        n[3 * i] = usable ? float(v.x) : 0.0f;
        n[3 * i + 1] = usable ? float(v.y) : 0.0f;
        n[3 * i + 2] = usable ? float(v.z) : 0.0f;
    }
    return n;
}

bool isNormalField(const ScalarField& f) {
    return std::any_of(std::begin(kVertexNormalFields), std::end(kVertexNormalFields),
                       [&](const char* n) { return f.name == n; });
}

}  // namespace

void setVertexNormals(SceneObject& o, const VertexNormals& normals) {
    std::erase_if(o.fields, isNormalField);
    const std::size_t n = normals.size() / 3;
    for (int a = 0; a < 3; ++a) {
        ScalarField f{kVertexNormalFields[a], ScalarField::Association::Point, std::vector<float>(n)};
        for (std::size_t i = 0; i < n; ++i) f.values[i] = normals[3 * i + std::size_t(a)];
        o.fields.push_back(std::move(f));
    }
}

VertexNormals takeVertexNormals(SceneObject& o) {
    VertexNormals n;
    const ScalarField *x = pointField(o, kVertexNormalFields[0]), *y = pointField(o, kVertexNormalFields[1]),
                      *z = pointField(o, kVertexNormalFields[2]);
    if (x && y && z) {
        n.resize(3 * x->values.size());
        for (std::size_t i = 0; i < x->values.size(); ++i) {
            n[3 * i] = x->values[i];
            n[3 * i + 1] = y->values[i];
            n[3 * i + 2] = z->values[i];
        }
    }
    std::erase_if(o.fields, isNormalField);
    return n;
}

VertexNormals fileVertexNormals(const SceneObject& o) {
    // PLY names its components nx, ny, nz; the readers split VTK's
    // three-component Normals into Normals_0, _1, _2.
    for (const auto& names : {std::array<const char*, 3>{"nx", "ny", "nz"},
                              std::array<const char*, 3>{"Normals_0", "Normals_1", "Normals_2"}}) {
        const ScalarField *x = pointField(o, names[0]), *y = pointField(o, names[1]), *z = pointField(o, names[2]);
        if (x && y && z) return unitNormals(*x, *y, *z);
    }
    return {};
}

void scaleVertexNormals(VertexNormals& normals, const Vec3& scale) {
    if (scale == Vec3{1, 1, 1}) return;
    for (std::size_t i = 0; i + 2 < normals.size(); i += 3) {
        const Vec3 n = normalize(Vec3{normals[i] / scale.x, normals[i + 1] / scale.y, normals[i + 2] / scale.z});
        const bool usable = std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z);  // not for scale 0
        normals[i] = usable ? float(n.x) : 0.0f;
        normals[i + 1] = usable ? float(n.y) : 0.0f;
        normals[i + 2] = usable ? float(n.z) : 0.0f;
    }
}

}  // namespace darkroom
