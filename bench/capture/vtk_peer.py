#!/usr/bin/python3
"""Peer for the capture benchmark: renders the same mesh, with the same camera
and resolution as bench_capture, with VTK 9.1 (Debian's python3-vtk9) and reads
back the z-buffer, as ttkCinemaImaging-style capture does.

Run offscreen under Xvfb:
    xvfb-run -a /usr/bin/python3 vtk_peer.py   (Debian's interpreter, where python3-vtk9 lives) --camera camera.json [--reps 7]
camera.json is written by `bench_capture --camera-json camera.json`.
Prints per-frame times for render alone and render + z-buffer read-back.
"""
import argparse
import json
import statistics
import sys
import time

import vtk  # noqa: F401  (python3-vtk9)
from vtkmodules.vtkIOGeometry import vtkOBJReader
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderer,
                                         vtkRenderWindow)
from vtkmodules.vtkCommonCore import vtkFloatArray
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (registers the OpenGL backend)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--camera", required=True, help="camera JSON written by bench_capture")
    ap.add_argument("--reps", type=int, default=7)
    args = ap.parse_args()
    with open(args.camera) as f:
        cam = json.load(f)

    reader = vtkOBJReader()
    reader.SetFileName(cam["mesh"])
    reader.Update()
    poly = reader.GetOutput()
    if poly.GetNumberOfPolys() == 0:
        sys.exit("vtk_peer: no polygons read from %s" % cam["mesh"])

    mapper = vtkPolyDataMapper()
    mapper.SetInputData(poly)
    mapper.ScalarVisibilityOff()
    actor = vtkActor()
    actor.SetMapper(mapper)
    ren = vtkRenderer()
    ren.AddActor(actor)
    ren.SetBackground(0, 0, 0)
    win = vtkRenderWindow()
    win.SetOffScreenRendering(1)
    win.AddRenderer(ren)
    win.SetSize(cam["width"], cam["height"])

    c = ren.GetActiveCamera()
    c.SetPosition(*cam["position"])
    c.SetFocalPoint(*cam["focal_point"])
    c.SetViewUp(*cam["view_up"])
    c.SetViewAngle(cam["view_angle"])
    ren.ResetCameraClippingRange()

    w, h = cam["width"], cam["height"]
    zbuf = vtkFloatArray()

    def frame(readback):
        # Modified() forces a real redraw each time instead of a cached one.
        actor.Modified()
        win.Render()
        if readback:
            win.GetZbufferData(0, 0, w - 1, h - 1, zbuf)

    frame(True)  # warm-up: shader compilation, buffer upload
    render_only, with_z = [], []
    for _ in range(args.reps):
        t0 = time.perf_counter()
        frame(False)
        # Without a read-back the GPU/driver may not have finished; glFinish
        # via a 1-pixel read makes the timing honest.
        win.GetZbufferData(0, 0, 0, 0, vtkFloatArray())
        render_only.append(time.perf_counter() - t0)
        t0 = time.perf_counter()
        frame(True)
        with_z.append(time.perf_counter() - t0)

    hits = sum(1 for i in range(0, zbuf.GetNumberOfTuples(), 97) if zbuf.GetValue(i) < 1.0)
    info = win.ReportCapabilities().splitlines()
    renderer = next((l for l in info if "OpenGL renderer" in l), "OpenGL renderer: ?")
    print("vtk %s, %s, %d triangles, %dx%d, %d reps (median)" %
          (vtk.vtkVersion.GetVTKVersion(), renderer.strip(), poly.GetNumberOfPolys(), w, h, args.reps))
    print("render only      %8.2f ms" % (statistics.median(render_only) * 1e3))
    print("render + z read  %8.2f ms  (z-buffer %d floats, ~%.0f%% sampled pixels covered)" %
          (statistics.median(with_z) * 1e3, zbuf.GetNumberOfTuples(),
           100.0 * hits / max(1, len(range(0, zbuf.GetNumberOfTuples(), 97)))))
    print("RESULT vtk_ms=%.3f" % (statistics.median(with_z) * 1e3))


if __name__ == "__main__":
    main()
