#pragma once
// Small geometry helpers shared by the generator tests.
#include <darkroom/math.h>
#include <darkroom/scene.h>

#include <cstdint>

namespace darkroom::test {

inline Vec3 vertexAt(const SceneObject& o, std::size_t i) {
    return {o.vertices[i * 4], o.vertices[i * 4 + 1], o.vertices[i * 4 + 2]};
}

// Unnormalised normal (v1 - v0) x (v2 - v0) of triangle t.
inline Vec3 triangleNormal(const SceneObject& o, std::size_t t) {
    const Vec3 a = vertexAt(o, o.indices[t * 3]), b = vertexAt(o, o.indices[t * 3 + 1]),
               c = vertexAt(o, o.indices[t * 3 + 2]);
    return cross(b - a, c - a);
}

inline Vec3 triangleCentroid(const SceneObject& o, std::size_t t) {
    return (vertexAt(o, o.indices[t * 3]) + vertexAt(o, o.indices[t * 3 + 1]) + vertexAt(o, o.indices[t * 3 + 2])) *
           (1.0 / 3);
}

}  // namespace darkroom::test
