#!/usr/bin/python3
"""Peer for bench_ssao_peer: VTK 9.1's vtkSSAOPass (what ParaView's render
view uses for ambient occlusion) on the same mesh, camera, resolution and
occlusion radius, kernel size 16, blur on, rendered offscreen through Mesa
(llvmpipe under Xvfb on a machine without a GPU).

Run under Xvfb with Debian's interpreter (where python3-vtk9 lives):
    xvfb-run -a /usr/bin/python3 vtk_ssao_peer.py --camera camera.json [--reps 9]
camera.json is written by `bench_ssao_peer --camera-json camera.json`.

The SSAO cost of a frame is the median frame time with the SSAO pass minus
the median frame time with VTK's plain render steps, every frame forced to
redraw and finished with a one-pixel read-back. Prints
"RESULT vtk_ssao_ms=<ms>" and the frame times.
"""
import argparse
import json
import statistics
import sys
import time

import vtk  # noqa: F401  (python3-vtk9)
from vtkmodules.vtkIOGeometry import vtkOBJReader
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer, vtkRenderWindow
from vtkmodules.vtkRenderingOpenGL2 import vtkRenderStepsPass, vtkSSAOPass
from vtkmodules.vtkCommonCore import vtkFloatArray


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--camera", required=True, help="camera JSON written by bench_ssao_peer")
    ap.add_argument("--reps", type=int, default=9)
    ap.add_argument("--kernel", type=int, default=16, help="vtkSSAOPass kernel size (samples per pixel)")
    ap.add_argument("--png", help="also write the SSAO frame here")
    args = ap.parse_args()
    with open(args.camera) as f:
        cam = json.load(f)

    reader = vtkOBJReader()
    reader.SetFileName(cam["mesh"])
    reader.Update()
    poly = reader.GetOutput()
    if poly.GetNumberOfPolys() == 0:
        sys.exit("vtk_ssao_peer: no polygons read from %s" % cam["mesh"])

    mapper = vtkPolyDataMapper()
    mapper.SetInputData(poly)
    mapper.ScalarVisibilityOff()
    actor = vtkActor()
    actor.SetMapper(mapper)
    ren = vtkRenderer()
    ren.AddActor(actor)
    ren.SetBackground(1, 1, 1)
    win = vtkRenderWindow()
    win.SetOffScreenRendering(1)
    win.AddRenderer(ren)
    w, h = cam["width"], cam["height"]
    win.SetSize(w, h)

    c = ren.GetActiveCamera()
    c.SetPosition(*cam["position"])
    c.SetFocalPoint(*cam["focal_point"])
    c.SetViewUp(*cam["view_up"])
    c.SetViewAngle(cam["view_angle"])
    ren.ResetCameraClippingRange()

    steps = vtkRenderStepsPass()
    ssao = vtkSSAOPass()
    ssao.SetDelegatePass(steps)
    ssao.SetRadius(cam["radius"])
    ssao.SetKernelSize(args.kernel)
    ssao.SetBias(0.01 * cam["radius"])
    ssao.SetBlur(True)

    pixel = vtkFloatArray()

    def frame():
        # Modified() forces a real redraw each time instead of a cached one;
        # the one-pixel read waits until the frame is finished (glFinish).
        actor.Modified()
        win.Render()
        win.GetZbufferData(0, 0, 0, 0, pixel)

    def timed(render_pass):
        ren.SetPass(render_pass)
        frame()  # warm-up: shader compilation, buffer allocation
        times = []
        for _ in range(args.reps):
            t0 = time.perf_counter()
            frame()
            times.append(time.perf_counter() - t0)
        return statistics.median(times) * 1e3, min(times) * 1e3

    plain_med, plain_min = timed(steps)
    ssao_med, ssao_min = timed(ssao)
    if args.png:
        from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter
        from vtkmodules.vtkIOImage import vtkPNGWriter
        grab = vtkWindowToImageFilter()
        grab.SetInput(win)
        grab.ReadFrontBufferOff()
        grab.Update()
        png = vtkPNGWriter()
        png.SetFileName(args.png)
        png.SetInputConnection(grab.GetOutputPort())
        png.Write()

    info = win.ReportCapabilities().splitlines()
    renderer = next((l for l in info if "OpenGL renderer" in l), "OpenGL renderer: ?").strip()
    print("vtk %s, %s, %d triangles, %dx%d, kernel %d, blur on, radius %.4g, %d reps (median)" %
          (vtk.vtkVersion.GetVTKVersion(), renderer, poly.GetNumberOfPolys(), w, h, args.kernel, cam["radius"],
           args.reps))
    print("frame without SSAO %8.2f ms  (min %.2f)" % (plain_med, plain_min))
    print("frame with SSAO    %8.2f ms  (min %.2f)" % (ssao_med, ssao_min))
    print("RESULT vtk_ssao_ms=%.3f" % (ssao_med - plain_med))


if __name__ == "__main__":
    main()
