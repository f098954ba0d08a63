// `isosurface`: the level set of demoField() with the point fields a capture
// usually colours by. Inside (f > isovalue) is the blobs' side.
#include "builtin_generators.h"
#include <darkroom/scene/marching_tetrahedra.h>

#include <darkroom/scene/generators.h>

#include <tbb/parallel_for.h>

namespace darkroom::generators {

IsosurfaceOptions readIsosurfaceOptions(GeneratorParams& p) {
    IsosurfaceOptions o;
    o.resolution = p.integer("resolution", o.resolution, 2, 512);
    // The field peaks at ~1.07 and is < 0.04 on the cube's faces: outside
    // this range the surface would be empty or cut open by the cube.
    o.isovalue = p.number("isovalue", o.isovalue, 0.05, 1.2);
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
    return obj;
}

}  // namespace darkroom::generators
