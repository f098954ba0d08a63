// Writes the capture-ingest benchmark's mesh: an N x N height field as a
// binary PLY (float x, y, z and a float point scalar "height"; 2 (N-1)^2
// triangles as 'list uchar int'), streamed row by row so that generating a
// 300M-triangle mesh needs no more memory than a row. Never committed: the
// benchmark script generates it into a temporary folder.
//
// Usage: make_height_field_ply OUT.ply N [--big-endian]
//   N = 4096 gives 33.5M triangles (704 MB), N = 12249 gives 300M (6.3 GB).
#include "height_field_terrain.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

using height_field::cellTriangles;
using height_field::coordinate;
using height_field::height;
using height_field::hostBigEndian;
using height_field::put;

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: %s OUT.ply N [--big-endian]\n", argv[0]);
        return 2;
    }
    const std::string path = argv[1];
    const long n = std::atol(argv[2]);
    const bool big = argc > 3 && std::strcmp(argv[3], "--big-endian") == 0;
    if (n < 2 || n > 65536) {
        std::fprintf(stderr, "N must be in [2, 65536]\n");
        return 2;
    }
    const bool swap = big != hostBigEndian();
    const std::uint64_t vertices = std::uint64_t(n) * std::uint64_t(n);
    const std::uint64_t faces = 2 * std::uint64_t(n - 1) * std::uint64_t(n - 1);
    std::ofstream out(path, std::ios::binary);
    out << "ply\nformat " << (big ? "binary_big_endian" : "binary_little_endian") << " 1.0\n"
        << "comment height field from bench/capture/make_height_field_ply\n"
        << "element vertex " << vertices << "\nproperty float x\nproperty float y\nproperty float z\n"
        << "property float height\nelement face " << faces << "\nproperty list uchar int vertex_indices\nend_header\n";
    std::vector<char> row;
    for (long j = 0; j < n; ++j) {
        row.clear();
        const double z = coordinate(j, n);
        for (long i = 0; i < n; ++i) {
            const double x = coordinate(i, n);
            const float h = height(x, z);
            for (float v : {float(x), h, float(z), h}) put(row, v, swap);
        }
        out.write(row.data(), std::streamsize(row.size()));
    }
    for (long j = 0; j + 1 < n; ++j) {
        row.clear();
        for (long i = 0; i + 1 < n; ++i) {
            std::int32_t tris[2][3];
            cellTriangles(i, j, n, tris);
            for (const auto& t : tris) {
                put(row, std::uint8_t(3), false);
                for (std::int32_t v : t) put(row, v, swap);
            }
        }
        out.write(row.data(), std::streamsize(row.size()));
    }
    out.close();
    if (!out) {
        std::fprintf(stderr, "%s: cannot write\n", path.c_str());
        return 1;
    }
    std::printf("wrote %s: %llu vertices, %llu triangles\n", path.c_str(), (unsigned long long)vertices,
                (unsigned long long)faces);
    return 0;
}
