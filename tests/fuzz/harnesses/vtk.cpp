// VTK legacy (ascii and binary), through the reader's file entry point.
// Property: whenever the direct reader of binary triangle meshes
// (framework/scene/src/vtk_legacy/legacy_triangles.h) takes an input, the
// general reader reads it too, to the same objects, bit for bit.
#include "harness.h"

#include <darkroom/error.h>
#include <darkroom/limits.h>
#include <darkroom/scene/mesh_readers.h>

#include <cstring>
#include <optional>
#include <vector>

namespace {

template <typename T>
bool sameBits(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

bool same(const std::vector<darkroom::SceneObject>& a, const std::vector<darkroom::SceneObject>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t k = 0; k < a.size(); ++k) {
        const auto &x = a[k], &y = b[k];
        if (x.name != y.name || x.representation != y.representation || !sameBits(x.vertices, y.vertices) ||
            x.indices != y.indices || x.primitiveCell != y.primitiveCell || x.fields.size() != y.fields.size())
            return false;
        for (std::size_t f = 0; f < x.fields.size(); ++f)
            if (x.fields[f].name != y.fields[f].name || x.fields[f].association != y.fields[f].association ||
                !sameBits(x.fields[f].values, y.fields[f].values))
                return false;
    }
    return true;
}

// The objects if the direct reader takes the file: with --max-input-bytes
// at 1 byte, the general reader refuses every file.
std::optional<std::vector<darkroom::SceneObject>> readDirectly(const std::string& path) {
    using darkroom::Limit;
    const std::uint64_t before = darkroom::limit(Limit::InputBytes);
    darkroom::setLimit(Limit::InputBytes, 1);
    std::optional<std::vector<darkroom::SceneObject>> objects;
    try {
        objects = darkroom::readVtkLegacy(path);
    } catch (const darkroom::Error&) {
    }
    darkroom::setLimit(Limit::InputBytes, before);
    return objects;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string path = fuzz::writeInput(data, size, "input.vtk");
    const auto direct = readDirectly(path);
    if (!direct) {
        try {
            (void)darkroom::readVtkLegacy(path);
        } catch (const darkroom::Error&) {
        }
        return 0;
    }
    darkroom::VtkLegacyReadOptions general;
    general.direct = false;
    std::vector<darkroom::SceneObject> objects;
    try {
        objects = darkroom::readVtkLegacy(path, general);
    } catch (const darkroom::Error&) {
        fuzz::expect(false, "the general reader reads what the direct reader takes");
    }
    fuzz::expect(same(*direct, objects), "the direct and the general reader give the same objects");
    return 0;
}
