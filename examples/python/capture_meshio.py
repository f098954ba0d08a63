"""A mesh of a format Darkroom has no reader for, brought in through meshio
(Debian's python3-meshio) without any file Darkroom reads: here a Gmsh
.msh file (written first by meshio itself, so the example needs nothing
else), captured from its arrays and shaded.

    PYTHONPATH=build/python python3 examples/python/capture_meshio.py [OUT_FOLDER]
"""
import pathlib
import sys

import meshio
import numpy as np

import darkroom as dr

out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
out.mkdir(parents=True, exist_ok=True)

# A Gmsh mesh of a bumpy sphere with a point field, as a mesher would write it.
u, v = np.meshgrid(np.linspace(0, np.pi, 48), np.linspace(0, 2 * np.pi, 96), indexing="ij")
r = 1 + 0.08 * np.sin(5 * u) * np.cos(4 * v)
points = np.stack([r * np.sin(u) * np.cos(v), r * np.sin(u) * np.sin(v), r * np.cos(u)], -1).reshape(-1, 3)
i = np.arange(48 * 96).reshape(48, 96)
a, b, c, d = i[:-1, :-1], i[:-1, 1:], i[1:, :-1], i[1:, 1:]
triangles = np.concatenate([np.stack([a, b, d], -1).reshape(-1, 3), np.stack([a, d, c], -1).reshape(-1, 3)])
meshio.write_points_cells(str(out / "bumpy.msh"), points, [("triangle", triangles)],
                          point_data={"bump": r.reshape(-1)}, file_format="gmsh22", binary=False)

# What a user does: meshio reads the format, Darkroom takes the arrays.
mesh = meshio.read(str(out / "bumpy.msh"))
scene = dr.Scene()
scene.add_triangles("bumpy", mesh.points, mesh.cells_dict["triangle"], point_fields={"bump": mesh.point_data["bump"]})
dr.capture(scene, dr.CameraGrid(resolution=(256, 256), phi=[30], theta=[20]), out / "bumpy.cdb", overwrite=True)

p = dr.Pipeline()
read = p.add("CinemaReader", database=dr.Database(out / "bumpy.cdb").path)
colour = p.add("ColorMapping", channel="bump", colormap="viridis")
p.connect(read.image, colour.image)
picture = p.evaluate(colour.image)
picture.save(str(out / "bumpy.png"))
print(f"{len(mesh.points)} points and {len(mesh.cells_dict['triangle'])} triangles from {out / 'bumpy.msh'}"
      f" captured and shaded into {out / 'bumpy.png'}")
