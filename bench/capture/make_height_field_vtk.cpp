// Writes the capture-ingest benchmark's mesh as BINARY legacy VTK: the same
// N x N height field as make_height_field_ply (float POINTS, 2 (N-1)^2
// triangles as POLYGONS, the float point scalar "height" as POINT_DATA
// SCALARS), big-endian as legacy VTK is, streamed row by row. Never
// committed: run_ingest_bench.sh --format vtk generates it.
//
// Usage: make_height_field_vtk OUT.vtk N [--offsets]
//   the classic cell layout (3 i j k as int per triangle), or with
//   --offsets VTK 5.1's OFFSETS/CONNECTIVITY (vtktypeint64), as VTK 9 writes.
//   N = 4096 gives 33.5M triangles (805 MB; 1.34 GB with --offsets).
#include "height_field_terrain.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace {

using height_field::cellTriangles;
using height_field::coordinate;
using height_field::height;
using height_field::put;

const bool kSwap = !height_field::hostBigEndian();

// Each row of points (x, y, z) or of "height" values.
void writePoints(std::ofstream& out, long n, bool heights) {
    std::vector<char> row;
    for (long j = 0; j < n; ++j) {
        row.clear();
        const double z = coordinate(j, n);
        for (long i = 0; i < n; ++i) {
            const double x = coordinate(i, n);
            const float h = height(x, z);
            if (heights) put(row, h, kSwap);
            else
                for (float v : {float(x), h, float(z)}) put(row, v, kSwap);
        }
        out.write(row.data(), std::streamsize(row.size()));
    }
}

// Each row of cells: classic (3 i j k as int), or 5.1's offsets
// (`offsets`) or connectivity (neither), as vtktypeint64.
void writeCells(std::ofstream& out, long n, bool classic, bool offsets) {
    std::vector<char> row;
    std::int64_t next = 0;
    if (offsets) {
        put(row, next, kSwap);
        out.write(row.data(), std::streamsize(row.size()));
    }
    for (long j = 0; j + 1 < n; ++j) {
        row.clear();
        for (long i = 0; i + 1 < n; ++i) {
            std::int32_t tris[2][3];
            cellTriangles(i, j, n, tris);
            for (const auto& t : tris) {
                if (offsets) {
                    put(row, next += 3, kSwap);
                    continue;
                }
                if (classic) put(row, std::int32_t(3), kSwap);
                for (std::int32_t v : t) {
                    if (classic) put(row, v, kSwap);
                    else put(row, std::int64_t(v), kSwap);
                }
            }
        }
        out.write(row.data(), std::streamsize(row.size()));
    }
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: %s OUT.vtk N [--offsets]\n", argv[0]);
        return 2;
    }
    const std::string path = argv[1];
    const long n = std::atol(argv[2]);
    const bool offsets = argc > 3 && std::strcmp(argv[3], "--offsets") == 0;
    if (n < 2 || n > 32768) {
        std::fprintf(stderr, "N must be in [2, 32768]\n");
        return 2;
    }
    const std::uint64_t points = std::uint64_t(n) * std::uint64_t(n);
    const std::uint64_t triangles = 2 * std::uint64_t(n - 1) * std::uint64_t(n - 1);
    std::ofstream out(path, std::ios::binary);
    out << "# vtk DataFile Version " << (offsets ? "5.1" : "3.0")
        << "\nheight field from bench/capture/make_height_field_vtk\nBINARY\nDATASET POLYDATA\nPOINTS " << points
        << " float\n";
    writePoints(out, n, false);
    if (offsets) {
        out << "\nPOLYGONS " << triangles + 1 << " " << 3 * triangles << "\nOFFSETS vtktypeint64\n";
        writeCells(out, n, false, true);
        out << "\nCONNECTIVITY vtktypeint64\n";
        writeCells(out, n, false, false);
    } else {
        out << "\nPOLYGONS " << triangles << " " << 4 * triangles << "\n";
        writeCells(out, n, true, false);
    }
    out << "\nPOINT_DATA " << points << "\nSCALARS height float 1\nLOOKUP_TABLE default\n";
    writePoints(out, n, true);
    out << "\n";
    out.close();
    if (!out) {
        std::fprintf(stderr, "%s: cannot write\n", path.c_str());
        return 1;
    }
    std::printf("wrote %s: %llu points, %llu triangles\n", path.c_str(), (unsigned long long)points,
                (unsigned long long)triangles);
    return 0;
}
