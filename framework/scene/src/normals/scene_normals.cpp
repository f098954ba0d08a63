#include "scene_normals.h"

namespace darkroom::scenefile {

VertexNormals takeShadingNormals(SceneObject& part) {
    VertexNormals n = takeVertexNormals(part);
    return n.empty() ? fileVertexNormals(part) : n;
}

void attachShadingNormals(Scene& scene, std::vector<VertexNormals>& held, double featureAngle) {
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        SceneObject& o = scene.objects[i];
        if (o.representation != Representation::Surface) continue;
        if (i < held.size() && held[i].size() == 3 * o.vertexCount()) setVertexNormals(o, held[i]);
        else averageVertexNormals(o, featureAngle);
        if (i < held.size()) VertexNormals().swap(held[i]);  // attached: let go of the copy
    }
}

}  // namespace darkroom::scenefile
