#include <darkroom/scene.h>

#include <algorithm>
#include <cmath>

namespace darkroom {

const char* toString(Representation r) {
    switch (r) {
        case Representation::Surface: return "surface";
        case Representation::Lines: return "lines";
        case Representation::Points: return "points";
    }
    return "?";
}

std::size_t SceneObject::primitiveCount() const {
    switch (representation) {
        case Representation::Surface: return indices.size() / 3;
        case Representation::Lines: return indices.size();
        case Representation::Points: return vertexCount();
    }
    return 0;
}

Bounds Scene::bounds() const {
    Bounds b;
    for (const auto& o : objects) {
        const bool round = o.representation != Representation::Surface;
        for (std::size_t i = 0; i + 3 < o.vertices.size(); i += 4) {
            const double r = round ? std::abs(o.vertices[i + 3]) : 0.0;
            b.lo = {std::min(b.lo.x, o.vertices[i] - r), std::min(b.lo.y, o.vertices[i + 1] - r),
                    std::min(b.lo.z, o.vertices[i + 2] - r)};
            b.hi = {std::max(b.hi.x, o.vertices[i] + r), std::max(b.hi.y, o.vertices[i + 1] + r),
                    std::max(b.hi.z, o.vertices[i + 2] + r)};
        }
    }
    return b;
}

}  // namespace darkroom
