#pragma once
// The capture-ingest benchmark's terrain and byte writer, shared by its
// generators (make_height_field_ply, make_height_field_vtk), so that the
// PLY and the legacy VTK file hold the same mesh.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

namespace height_field {

inline bool hostBigEndian() {
    const std::uint16_t one = 1;
    unsigned char b;
    std::memcpy(&b, &one, 1);
    return b == 0;
}

template <typename T>
void put(std::vector<char>& out, T v, bool swap) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    if (swap)
        for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
    out.insert(out.end(), b, b + sizeof(T));
}

// A smooth terrain with bumps at several scales over [-1, 1]^2, y up.
inline float height(double x, double z) {
    return float(0.15 * std::sin(3.1 * x) * std::cos(2.3 * z) + 0.05 * std::sin(17.0 * x + 5.0 * z) +
                 0.01 * std::cos(61.0 * z - 37.0 * x));
}

// Grid coordinate i of n in [-1, 1].
inline double coordinate(long i, long n) { return -1.0 + 2.0 * double(i) / double(n - 1); }

// The two triangles of grid cell (i, j) of an n-wide grid, as the PLY writes them.
inline void cellTriangles(long i, long j, long n, std::int32_t tris[2][3]) {
    const auto a = std::int32_t(j * n + i), b = a + 1, c = std::int32_t(a + n), d = c + 1;
    const std::int32_t t[2][3] = {{a, c, b}, {b, c, d}};
    std::memcpy(tris, t, sizeof t);
}

}  // namespace height_field
