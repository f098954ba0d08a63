#include "legacy_triangles.h"

#include "../poly_mesh.h"
#include "../windowed/record_windows.h"
#include "../windowed/typed_load.h"
#include "legacy_layout.h"

#include <darkroom/limits.h>

#include <string>
#include <type_traits>
#include <vector>

namespace darkroom::vtk_legacy {
namespace {

using windowed::FileRangeReader;
using windowed::load;
using windowed::Span;
using windowed::withType;

// Legacy VTK's binary arrays are big-endian whatever wrote them.
const bool kSwap = !mesh::isHostBigEndian();

// An index of type T at p, if it is a whole number below `limit`.
template <typename T>
std::optional<std::uint64_t> indexAt(const char* p, std::uint64_t limit) {
    const T v = load<T>(p, kSwap);
    if constexpr (std::is_signed_v<T>)
        if (v < 0) return std::nullopt;
    if (std::uint64_t(v) >= limit) return std::nullopt;
    return std::uint64_t(v);
}

// Classic cells (3, i, j, k as int): false at the first that is not a
// triangle of points in [0, points).
bool decodeCells(const Span& s, std::uint32_t* indices, std::uint64_t points) {
    const char* p = s.window + s.begin * 16;
    std::uint32_t* out = indices + 3 * (s.first + s.begin);
    for (std::size_t i = s.begin; i < s.end; ++i, p += 16, out += 3) {
        if (load<std::int32_t>(p, kSwap) != 3) return false;
        for (std::size_t k = 0; k < 3; ++k) {
            const auto v = indexAt<std::int32_t>(p + 4 + 4 * k, points);
            if (!v) return false;
            out[k] = std::uint32_t(*v);
        }
    }
    return true;
}

// 5.1 offsets: false unless offset i is 3 i (every cell a triangle).
bool decodeOffsets(const Span& s, mesh::ValueType type) {
    return withType(type, [&](auto tag) {
        using T = decltype(tag);
        if constexpr (std::is_floating_point_v<T>) {
            return false;
        } else {
            const char* p = s.window + s.begin * sizeof(T);
            for (std::size_t i = s.first + s.begin; i < s.first + s.end; ++i, p += sizeof(T))
                if (indexAt<T>(p, std::uint64_t(-1)) != std::optional<std::uint64_t>(3 * i)) return false;
            return true;
        }
    });
}

// 5.1 connectivity: false at the first index outside [0, points).
bool decodeConnectivity(const Span& s, mesh::ValueType type, std::uint32_t* indices, std::uint64_t points) {
    return withType(type, [&](auto tag) {
        using T = decltype(tag);
        if constexpr (std::is_floating_point_v<T>) {
            return false;
        } else {
            const char* p = s.window + s.begin * sizeof(T);
            for (std::size_t i = s.first + s.begin; i < s.first + s.end; ++i, p += sizeof(T)) {
                const auto v = indexAt<T>(p, points);
                if (!v) return false;
                indices[i] = std::uint32_t(*v);
            }
            return true;
        }
    });
}

// Record i (`components` floats or doubles) goes to
// out[where[i] * stride + k], as the float the general reader stores,
// unless the point is dropped (no triangle uses it).
void scatter(const Span& s, mesh::ValueType type, std::size_t components, const std::uint32_t* where, float* out,
             std::size_t stride) {
    withType(type, [&](auto tag) {
        using T = decltype(tag);
        const char* p = s.window + s.begin * components * sizeof(T);
        for (std::size_t i = s.first + s.begin; i < s.first + s.end; ++i, p += components * sizeof(T)) {
            if (where[i] == mesh::kStripRestart) continue;
            float* o = out + std::size_t(where[i]) * stride;
            for (std::size_t k = 0; k < components; ++k) o[k] = windowed::storedFloat(load<T>(p + k * sizeof(T), kSwap));
        }
    });
}

// The triangles' indices, into `indices` (3 per triangle); false if any
// cell is not a triangle of the mesh's points, or the file ends early.
bool readIndices(const FileRangeReader& file, const TriangleLayout& l, std::uint32_t* indices, std::size_t window,
                 std::vector<char>& buffer) {
    if (!l.offsetsLayout)
        return windowed::readRecords(file, l.cells.offset, l.triangleCount, 16, window, buffer,
                                     [&](const Span& s) { return decodeCells(s, indices, l.pointCount); });
    const std::size_t offsetSize = mesh::sizeOf(l.offsets.type), indexSize = mesh::sizeOf(l.connectivity.type);
    return windowed::readRecords(file, l.offsets.offset, l.offsets.count, offsetSize, window, buffer,
                                 [&](const Span& s) { return decodeOffsets(s, l.offsets.type); }) &&
           windowed::readRecords(file, l.connectivity.offset, l.connectivity.count, indexSize, window, buffer,
                                 [&](const Span& s) {
                                     return decodeConnectivity(s, l.connectivity.type, indices, l.pointCount);
                                 });
}

}  // namespace

std::optional<SceneObject> readTriangles(const std::string& path, const std::string& name, std::size_t windowBytes) {
    const FileRangeReader file(path);
    if (!file.ok()) return std::nullopt;
    const std::optional<TriangleLayout> layout = scanTriangleLayout(file);
    if (!layout) return std::nullopt;
    // The file holds every array (scanned), so each is at most about the
    // file's size; the limit still applies to what is decoded.
    checkBytes(Limit::DecodedBytes, layout->triangleCount * 12, path,
               std::to_string(layout->triangleCount) + " triangles' indices");
    checkBytes(Limit::DecodedBytes, layout->pointCount * 16, path, std::to_string(layout->pointCount) + " points");

    // Triangles first (their points' numbering depends on them), then the
    // points and their scalars, each written straight to its new number.
    SceneObject object;
    object.name = name;
    object.indices.resize(std::size_t(3 * layout->triangleCount));
    std::vector<char> buffer;
    if (!readIndices(file, *layout, object.indices.data(), windowBytes, buffer)) return std::nullopt;
    std::size_t used = 0;
    const std::vector<std::uint32_t> newNumber =
        mesh::renumberByFirstUse(object.indices, std::size_t(layout->pointCount), used);
    const std::uint32_t* where = newNumber.data();
    object.vertices.assign(4 * used, 0.f);
    const ArrayAt& points = layout->points;
    const std::size_t pointSize = 3 * mesh::sizeOf(points.type);
    if (!windowed::readRecords(file, points.offset, std::size_t(layout->pointCount), pointSize, windowBytes, buffer,
                               [&](const Span& s) {
                                   scatter(s, points.type, 3, where, object.vertices.data(), 4);
                                   return true;
                               }))
        return std::nullopt;
    for (const auto& scalars : layout->pointScalars) {
        const ArrayAt& values = scalars.second;
        object.fields.push_back({scalars.first, ScalarField::Association::Point, std::vector<float>(used)});
        float* out = object.fields.back().values.data();
        if (!windowed::readRecords(file, values.offset, std::size_t(values.count), mesh::sizeOf(values.type),
                                   windowBytes, buffer, [&](const Span& s) {
                                       scatter(s, values.type, 1, where, out, 1);
                                       return true;
                                   }))
            return std::nullopt;
    }
    return object;
}

}  // namespace darkroom::vtk_legacy
