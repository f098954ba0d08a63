#!/usr/bin/env python3
"""Writes a tetrahedral VTK unstructured grid (.vtu, ASCII) for the volume example.

The cube [-1, 1]^3 is cut into n^3 cells, each split into the six Kuhn
tetrahedra around its main diagonal. Point fields: `field` (three Gaussian
blobs, peaks near 1) and `height` (= z); cell field `cell` (the index of the
grid cell the tetrahedron came from). Independent of Darkroom's code, so the
reader is tested on a file it did not write.

usage: make_tetrahedra.py OUT.vtu [n]   (n = cells per axis, default 24)
"""
import itertools
import math
import os
import sys

BLOBS = [((-0.35, -0.2, 0.1), 0.45, 1.0), ((0.4, 0.25, -0.15), 0.4, 0.9), ((0.05, 0.3, 0.55), 0.3, 0.8)]


def field(x, y, z):
    return sum(a * math.exp(-((x - c[0]) ** 2 + (y - c[1]) ** 2 + (z - c[2]) ** 2) / (s * s)) for c, s, a in BLOBS)


def main():
    out = sys.argv[1]
    n = int(sys.argv[2]) if len(sys.argv) > 2 else 24
    m = n + 1
    coord = [-1 + 2 * i / n for i in range(m)]
    points = [(coord[i], coord[j], coord[k]) for k in range(m) for j in range(m) for i in range(m)]

    def pid(i, j, k):
        return i + m * (j + m * k)

    tets, cells = [], []
    for k, j, i in itertools.product(range(n), repeat=3):
        for order in itertools.permutations(range(3)):
            corner = [0, 0, 0]
            path = [pid(i, j, k)]
            for axis in order:
                corner[axis] += 1
                path.append(pid(i + corner[0], j + corner[1], k + corner[2]))
            a, b, c, d = (points[p] for p in path)
            u, v, w = [[q[t] - a[t] for t in range(3)] for q in (b, c, d)]
            det = (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
                   + u[2] * (v[0] * w[1] - v[1] * w[0]))
            if det < 0:  # VTK's tetrahedra have positive volume
                path[2], path[3] = path[3], path[2]
            tets.append(path)
            cells.append(i + n * (j + n * k))

    def lines(values, per_line=12):
        values = list(values)
        return "\n".join(" ".join(values[s:s + per_line]) for s in range(0, len(values), per_line))

    tmp = out + ".tmp"
    with open(tmp, "w") as f:
        f.write('<?xml version="1.0"?>\n<VTKFile type="UnstructuredGrid" version="1.0" byte_order="LittleEndian" '
                'header_type="UInt64">\n  <UnstructuredGrid>\n')
        f.write(f'    <Piece NumberOfPoints="{len(points)}" NumberOfCells="{len(tets)}">\n      <PointData>\n')
        f.write('        <DataArray type="Float32" Name="field" format="ascii">\n')
        f.write(lines(f"{field(*p):.6g}" for p in points) + "\n        </DataArray>\n")
        f.write('        <DataArray type="Float32" Name="height" format="ascii">\n')
        f.write(lines(f"{p[2]:.6g}" for p in points) + "\n        </DataArray>\n      </PointData>\n")
        f.write('      <CellData>\n        <DataArray type="Int32" Name="cell" format="ascii">\n')
        f.write(lines(str(c) for c in cells) + "\n        </DataArray>\n      </CellData>\n")
        f.write('      <Points>\n        <DataArray type="Float32" NumberOfComponents="3" format="ascii">\n')
        f.write(lines((f"{x:.6g} {y:.6g} {z:.6g}" for x, y, z in points), 4) + "\n        </DataArray>\n      </Points>\n")
        f.write('      <Cells>\n        <DataArray type="Int64" Name="connectivity" format="ascii">\n')
        f.write(lines(str(p) for t in tets for p in t) + "\n        </DataArray>\n")
        f.write('        <DataArray type="Int64" Name="offsets" format="ascii">\n')
        f.write(lines(str(4 * (c + 1)) for c in range(len(tets))) + "\n        </DataArray>\n")
        f.write('        <DataArray type="UInt8" Name="types" format="ascii">\n')
        f.write(lines("10" for _ in tets) + "\n        </DataArray>\n      </Cells>\n")
        f.write("    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n")
    os.replace(tmp, out)


if __name__ == "__main__":
    main()
