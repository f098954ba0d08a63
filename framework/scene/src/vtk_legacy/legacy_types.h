#pragma once
// Legacy VTK's names of its value types, shared by the general reader
// (vtk_legacy_reader.cpp) and the direct one (legacy_triangles.h), so that
// both take the same files.
#include <darkroom/data/formats/binary_values.h>

#include <optional>
#include <string_view>

namespace darkroom::vtk_legacy {

inline std::optional<mesh::ValueType> legacyType(std::string_view s) {
    using mesh::ValueType;
    if (s == "char") return ValueType::Int8;
    if (s == "unsigned_char") return ValueType::UInt8;
    if (s == "short") return ValueType::Int16;
    if (s == "unsigned_short") return ValueType::UInt16;
    if (s == "int") return ValueType::Int32;
    if (s == "unsigned_int") return ValueType::UInt32;
    if (s == "long" || s == "vtktypeint64") return ValueType::Int64;
    if (s == "unsigned_long" || s == "vtktypeuint64") return ValueType::UInt64;
    if (s == "float") return ValueType::Float32;
    if (s == "double") return ValueType::Float64;
    return std::nullopt;
}

}  // namespace darkroom::vtk_legacy
