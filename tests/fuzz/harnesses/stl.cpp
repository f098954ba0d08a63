// STL (ASCII and binary), through the reader's file entry point. Beyond not
// crashing: what it returns is one surface whose indices all name a vertex,
// one triangle a cell (the identity map left implied), finite positions, and
// no two vertices at the same position (the reader merges them).
#include "harness.h"

#include <darkroom/error.h>
#include <darkroom/scene/mesh_readers.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        const auto objects = darkroom::readStl(fuzz::writeInput(data, size, "input.stl"));
        fuzz::expect(objects.size() == 1, "one object");
        const darkroom::SceneObject& o = objects[0];
        fuzz::expect(o.representation == darkroom::Representation::Surface, "a surface");
        fuzz::expect(!o.indices.empty() && o.indices.size() % 3 == 0, "whole triangles, at least one");
        fuzz::expect(o.primitiveCell.empty(), "each triangle its own cell");
        for (std::uint32_t i : o.indices) fuzz::expect(i < o.vertexCount(), "every index names a vertex");
        fuzz::expect(o.vertexCount() <= o.indices.size(), "no more vertices than corners");
        std::vector<std::array<float, 3>> positions;
        for (std::size_t v = 0; v < o.vertexCount(); ++v) {
            const float* p = o.vertices.data() + 4 * v;
            fuzz::expect(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]), "finite positions");
            // +0 for -0, as the reader keys them.
            positions.push_back({p[0] + 0.f, p[1] + 0.f, p[2] + 0.f});
        }
        std::sort(positions.begin(), positions.end());
        fuzz::expect(std::adjacent_find(positions.begin(), positions.end()) == positions.end(),
                     "each position once (identical corners merged)");
    } catch (const darkroom::Error&) {
    }
    return 0;
}
