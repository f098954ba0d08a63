#!/usr/bin/python3
"""Peer for bench_volume: the same file read and drawn with VTK 9.1's own
readers and filters (Debian's python3-vtk9): vtkXMLUnstructuredGridReader /
vtkXMLImageDataReader, vtkGeometryFilter (boundary surface), vtkContourFilter
(isosurface, with the other point fields interpolated) and vtkCutter (slice),
each followed by vtkTriangleFilter so triangle counts compare. Prints RESULT
lines like bench_volume's (median of --reps runs, milliseconds).

    /usr/bin/python3 vtk_volume_peer.py FILE.vtu --field field --value 0.5 [--reps 5]
    /usr/bin/python3 vtk_volume_peer.py FILE.vtu --write-binary OUT.vtu   (converts, then exits)
"""
import argparse
import statistics
import time

from vtkmodules.vtkCommonDataModel import vtkPlane
from vtkmodules.vtkFiltersCore import vtkContourFilter, vtkCutter, vtkTriangleFilter
from vtkmodules.vtkFiltersGeometry import vtkGeometryFilter
from vtkmodules.vtkIOXML import (vtkXMLImageDataReader, vtkXMLUnstructuredGridReader,
                                 vtkXMLUnstructuredGridWriter)


def median_ms(reps, f):
    times, result = [], None
    for _ in range(reps):
        t = time.perf_counter()
        result = f()
        times.append((time.perf_counter() - t) * 1000)
    return statistics.median(times), result


def triangles(algorithm):
    tri = vtkTriangleFilter()
    tri.SetInputConnection(algorithm.GetOutputPort())
    tri.Update()
    return tri.GetOutput().GetNumberOfCells()


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("path")
    ap.add_argument("--field", default="field")
    ap.add_argument("--value", type=float, default=0.5)
    ap.add_argument("--reps", type=int, default=5)
    ap.add_argument("--write-binary")
    args = ap.parse_args()

    def read():
        r = vtkXMLImageDataReader() if args.path.endswith(".vti") else vtkXMLUnstructuredGridReader()
        r.SetFileName(args.path)
        r.Update()
        return r.GetOutput()

    read_ms, data = median_ms(args.reps, read)
    if args.write_binary:
        w = vtkXMLUnstructuredGridWriter()
        w.SetInputData(data)
        w.SetDataModeToAppended()
        w.EncodeAppendedDataOff()
        w.SetCompressorTypeToNone()
        w.SetFileName(args.write_binary)
        w.Write()
        return
    data.GetPointData().SetActiveScalars(args.field)
    bounds = data.GetBounds()
    centre = [(bounds[2 * a] + bounds[2 * a + 1]) / 2 for a in range(3)]
    centre[2] += 0.013 * (bounds[5] - bounds[4])  # as bench_volume: off the grid layers

    def boundary():
        f = vtkGeometryFilter()
        f.SetInputData(data)
        f.Update()
        return triangles(f)

    def iso():
        f = vtkContourFilter()
        f.SetInputData(data)
        f.SetValue(0, args.value)
        f.SetInputArrayToProcess(0, 0, 0, 0, args.field)
        f.ComputeScalarsOff()
        f.Update()
        return triangles(f)

    def cut():
        plane = vtkPlane()
        plane.SetOrigin(centre)
        plane.SetNormal(0, 0, 1)
        f = vtkCutter()
        f.SetInputData(data)
        f.SetCutFunction(plane)
        f.Update()
        return triangles(f)

    boundary_ms, nb = median_ms(args.reps, boundary)
    iso_ms, ni = median_ms(args.reps, iso)
    slice_ms, ns = median_ms(args.reps, cut)
    print(f"{args.path}: {data.GetNumberOfPoints()} points, {data.GetNumberOfCells()} cells (VTK {__import__('vtk').vtkVersion.GetVTKVersion()})")
    print(f"RESULT read_ms={read_ms:.2f} boundary_ms={boundary_ms:.2f} isosurface_ms={iso_ms:.2f} slice_ms={slice_ms:.2f}")
    print(f"TRIANGLES boundary={nb} isosurface={ni} slice={ns}")


if __name__ == "__main__":
    main()
