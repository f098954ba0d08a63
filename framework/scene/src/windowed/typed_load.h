#pragma once
// Values of a binary mesh file's numeric types, loaded in either byte order,
// with the loops over them compiled per type (the direct readers decode
// hundreds of millions of values; a switch per value would dominate).
#include <darkroom/data/formats/binary_values.h>

#include <algorithm>
#include <cstdint>
#include <cstring>

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
