#pragma once
// Typed values in files of either byte order (PLY, legacy VTK, VTK XML).
#include <cstdint>
#include <cstring>
#include <optional>
#include <string_view>

namespace darkroom::mesh {

enum class ValueType : std::uint8_t { Int8, UInt8, Int16, UInt16, Int32, UInt32, Int64, UInt64, Float32, Float64 };

inline std::size_t sizeOf(ValueType t) {
    switch (t) {
        case ValueType::Int8: case ValueType::UInt8: return 1;
        case ValueType::Int16: case ValueType::UInt16: return 2;
        case ValueType::Int32: case ValueType::UInt32: case ValueType::Float32: return 4;
        default: return 8;
    }
}

inline bool isHostBigEndian() {
    const std::uint16_t one = 1;
    unsigned char b;
    std::memcpy(&b, &one, 1);
    return b == 0;
}

// Loads one value of type t from p, stored big- or little-endian.
inline double loadValue(ValueType t, const char* p, bool bigEndian) {
    unsigned char b[8];
    const std::size_t n = sizeOf(t);
    std::memcpy(b, p, n);
    if (bigEndian != isHostBigEndian())
        for (std::size_t i = 0; i < n / 2; ++i) std::swap(b[i], b[n - 1 - i]);
    switch (t) {
        case ValueType::Int8: { std::int8_t v; std::memcpy(&v, b, 1); return v; }
        case ValueType::UInt8: return b[0];
        case ValueType::Int16: { std::int16_t v; std::memcpy(&v, b, 2); return v; }
        case ValueType::UInt16: { std::uint16_t v; std::memcpy(&v, b, 2); return v; }
        case ValueType::Int32: { std::int32_t v; std::memcpy(&v, b, 4); return v; }
        case ValueType::UInt32: { std::uint32_t v; std::memcpy(&v, b, 4); return v; }
        case ValueType::Int64: { std::int64_t v; std::memcpy(&v, b, 8); return double(v); }
        case ValueType::UInt64: { std::uint64_t v; std::memcpy(&v, b, 8); return double(v); }
        case ValueType::Float32: { float v; std::memcpy(&v, b, 4); return v; }
        case ValueType::Float64: { double v; std::memcpy(&v, b, 8); return v; }
    }
    return 0;
}

// VTK XML names (Float32, Int64, ...).
inline std::optional<ValueType> vtkXmlType(std::string_view s) {
    if (s == "Int8") return ValueType::Int8;
    if (s == "UInt8") return ValueType::UInt8;
    if (s == "Int16") return ValueType::Int16;
    if (s == "UInt16") return ValueType::UInt16;
    if (s == "Int32") return ValueType::Int32;
    if (s == "UInt32") return ValueType::UInt32;
    if (s == "Int64") return ValueType::Int64;
    if (s == "UInt64") return ValueType::UInt64;
    if (s == "Float32") return ValueType::Float32;
    if (s == "Float64") return ValueType::Float64;
    return std::nullopt;
}

}  // namespace darkroom::mesh
