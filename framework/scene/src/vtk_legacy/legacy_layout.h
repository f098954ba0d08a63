#pragma once
// Where the arrays of a binary legacy VTK triangle mesh lie in its file.
// The keyword lines between the arrays are read a small window at a time,
// exactly as the general reader's cursor reads them (vtk_legacy_reader.cpp),
// and each array is skipped by its size, so that finding them reads a few
// kilobytes of a file of any size.
#include "../windowed/file_range_reader.h"

#include <darkroom/data/formats/binary_values.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace darkroom::vtk_legacy {

// `count` big-endian values of `type` from byte `offset` of the file.
struct ArrayAt {
    std::uint64_t offset = 0;
    std::uint64_t count = 0;
    mesh::ValueType type = mesh::ValueType::Float32;

    std::uint64_t bytes() const { return count * mesh::sizeOf(type); }
};

struct TriangleLayout {
    std::uint64_t pointCount = 0, triangleCount = 0;
    ArrayAt points;  // x, y, z per point, float or double
    // The classic layout: `cells` holds 4 int per triangle (3, i, j, k).
    // VTK 5.1's: `offsets` (0, 3, 6, ..., one more than the triangles) and
    // `connectivity` (i, j, k per triangle), of an integer type.
    bool offsetsLayout = false;
    ArrayAt cells, offsets, connectivity;
    std::vector<std::pair<std::string, ArrayAt>> pointScalars;  // 1 component each, in file order
};

// The layout of `file` if it is a BINARY POLYDATA of POINTS (float or
// double), one POLYGONS list sized for triangles alone (classic: a size of
// 4 per cell; 5.1: 3 connectivity entries per cell, offsets and
// connectivity of an integer type) and optionally POINT_DATA of every point
// with 1-component float or double SCALARS; every array within the file.
// Nothing for any other file (ASCII, other datasets, cells of other kinds,
// CELL_DATA, FIELD, VECTORS, METADATA, ...), which the general reader reads,
// or refuses in its own words. The cells' values are not read here.
std::optional<TriangleLayout> scanTriangleLayout(const windowed::FileRangeReader& file);

}  // namespace darkroom::vtk_legacy
