// `isosurface`: the level set of demoField() with the point fields a capture
// usually colours by. Inside (f > isovalue) is the blobs' side.
#include "builtin_generators.h"
#include <darkroom/scene/marching_tetrahedra.h>

#include <darkroom/scene/generators.h>
#include <darkroom/scene/vertex_normals.h>

#include <tbb/parallel_for.h>

namespace darkroom::generators {

IsosurfaceOptions readIsosurfaceOptions(GeneratorParams& p) {
    IsosurfaceOptions o;
    o.resolution = p.integer("resolution", o.resolution, 2, 512);
    // The field peaks at ~1.07 and is < 0.04 on the cube's faces: outside
    // this range the surface would be empty or cut open by the cube.
    o.isovalue = p.number("isovalue", o.isovalue, 0.05, 1.2);
    o.normals = p.vertexNormals();
    p.finish();
    return o;
}

SceneObject buildIsosurface(const IsosurfaceOptions& o) {
    LevelSetGrid grid;
    grid.samples = o.resolution;
    const LevelSetMesh mesh = extractLevelSet(demoField, grid, o.isovalue, /*refine=*/true);

    SceneObject obj;
    obj.name = "isosurface";
    obj.representation = Representation::Surface;
    const std::size_t n = mesh.positions.size();
    obj.vertices.resize(n * 4);
    obj.indices = mesh.triangles;
    ScalarField height{"height", ScalarField::Association::Point, std::vector<float>(n)};
    ScalarField value{"field", ScalarField::Association::Point, std::vector<float>(n)};
    ScalarField gradient{"gradient magnitude", ScalarField::Association::Point, std::vector<float>(n)};
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
        const Vec3& p = mesh.positions[i];
        float* v = &obj.vertices[i * 4];
        v[0] = float(p.x), v[1] = float(p.y), v[2] = float(p.z), v[3] = 0.f;
        height.values[i] = float(p.z);
        value.values[i] = float(demoField(p));
        gradient.values[i] = float(length(demoFieldGradient(p)));
    });
    obj.fields = {std::move(height), std::move(value), std::move(gradient)};
    if (o.normals) {
        // The exact normal of the level set: the gradient, reversed so that
        // it points outwards (f falls outwards), as the triangles do.
        VertexNormals normals(3 * n);
        tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
            const Vec3 d = normalize(demoFieldGradient(mesh.positions[i])) * -1.0;
            normals[3 * i] = float(d.x), normals[3 * i + 1] = float(d.y), normals[3 * i + 2] = float(d.z);
        });
        setVertexNormals(obj, normals);
    }
    return obj;
}

}  // namespace darkroom::generators
