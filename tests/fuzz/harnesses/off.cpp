// OFF (ASCII, with its COFF/NOFF/... variants), through the reader's file
// entry point. Beyond not crashing: what it returns is one surface (or, for a
// file without faces, one point cloud) whose indices all name a vertex, whose
// triangles map in file order to their faces, and whose positions are finite
// (the reader refuses non-finite coordinates).
#include "harness.h"

#include <darkroom/error.h>
#include <darkroom/scene/mesh_readers.h>

#include <cmath>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        const auto objects = darkroom::readOff(fuzz::writeInput(data, size, "input.off"));
        fuzz::expect(objects.size() == 1, "one object: the surface, or the point cloud of a file without faces");
        const darkroom::SceneObject& o = objects[0];
        fuzz::expect(o.vertexCount() > 0, "at least one vertex");
        for (float v : o.vertices) fuzz::expect(std::isfinite(v), "finite positions (radius 0)");
        if (o.representation == darkroom::Representation::Points) {
            fuzz::expect(o.indices.empty(), "a point cloud has no indices");
            return 0;
        }
        fuzz::expect(o.representation == darkroom::Representation::Surface, "faces make a surface");
        fuzz::expect(o.indices.size() % 3 == 0, "whole triangles");
        for (std::uint32_t i : o.indices) fuzz::expect(i < o.vertexCount(), "every index names a vertex");
        const std::size_t triangles = o.indices.size() / 3;
        fuzz::expect(o.primitiveCell.empty() || o.primitiveCell.size() == triangles, "one face per triangle");
        for (std::size_t t = 1; t < o.primitiveCell.size(); ++t)
            fuzz::expect(o.primitiveCell[t] >= o.primitiveCell[t - 1], "triangles in their faces' order");
    } catch (const darkroom::Error&) {
    }
    return 0;
}
