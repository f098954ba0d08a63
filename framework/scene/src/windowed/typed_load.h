#pragma once
// Values of a binary mesh file's numeric types, loaded in either byte order,
// with the loops over them compiled per type (the direct readers decode
// hundreds of millions of values; a switch per value would dominate).
#include <darkroom/data/formats/binary_values.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace darkroom::windowed {

template <typename T>
T load(const char* p, bool swap) {
    unsigned char b[sizeof(T)];
    std::memcpy(b, p, sizeof(T));
    if (swap) std::reverse(b, b + sizeof(T));
    T v;
    std::memcpy(&v, b, sizeof(T));
    return v;
}

// The float the general legacy VTK reader stores for a value of the file:
// its double (kept in an array of doubles) narrowed to float. For a float
// that is the value itself, except that a signalling NaN comes out quiet
// (widening sets the quiet bit); the compiler folds float(double(f)) to f,
// so the bit is set here, and both readers give the same bits.
template <typename T>
float storedFloat(T v) {
    if constexpr (std::is_same_v<T, float>) {
        if (v == v) return v;
        std::uint32_t bits;
        std::memcpy(&bits, &v, 4);
        bits |= 0x00400000u;
        std::memcpy(&v, &bits, 4);
        return v;
    } else {
        return float(double(v));
    }
}

// f(T{}) for the C++ type of a file's value type.
template <typename F>
decltype(auto) withType(mesh::ValueType t, F&& f) {
    using mesh::ValueType;
    switch (t) {
        case ValueType::Int8: return f(std::int8_t{});
        case ValueType::UInt8: return f(std::uint8_t{});
        case ValueType::Int16: return f(std::int16_t{});
        case ValueType::UInt16: return f(std::uint16_t{});
        case ValueType::Int32: return f(std::int32_t{});
        case ValueType::UInt32: return f(std::uint32_t{});
        case ValueType::Int64: return f(std::int64_t{});
        case ValueType::UInt64: return f(std::uint64_t{});
        case ValueType::Float32: return f(float{});
        case ValueType::Float64: break;
    }
    return f(double{});
}

}  // namespace darkroom::windowed
