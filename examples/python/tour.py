"""A tour of darkroom in Python (docs/python.md): capture a scene made of
numpy arrays into a Cinema database, open the database, shade an entry,
change the colour map, and save what it shows. The notebook tour.ipynb
does the same, step by step, with the pictures inline.

    PYTHONPATH=build/python python3 examples/python/tour.py [OUT_FOLDER]
"""
import pathlib
import sys

import numpy as np

import darkroom as dr

out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
out.mkdir(parents=True, exist_ok=True)

# A wavy torus with a field, captured from two sides (depth, the field, normals).
u, v = np.meshgrid(np.linspace(0, 2 * np.pi, 96), np.linspace(0, 2 * np.pi, 48), indexing="ij")
tube = 0.35 + 0.05 * np.sin(6 * u)
verts = np.stack([(1 + tube * np.cos(v)) * np.cos(u), (1 + tube * np.cos(v)) * np.sin(u), tube * np.sin(v)], -1)
verts = verts.reshape(-1, 3).astype(np.float32)
i = np.arange(96 * 48).reshape(96, 48)
a, b, c, d = i, np.roll(i, -1, 1), np.roll(i, -1, 0), np.roll(np.roll(i, -1, 0), -1, 1)
tris = np.concatenate([np.stack([a, b, d], -1).reshape(-1, 3), np.stack([a, d, c], -1).reshape(-1, 3)])
scene = dr.Scene()
scene.add_triangles("torus", verts, tris, point_fields={"wave": np.sin(6 * u).reshape(-1)})
rows = dr.capture(scene, dr.CameraGrid(resolution=(320, 240), phi=[0, 60], theta=[35]), out / "torus.cdb",
                  overwrite=True, normals=True)
print(f"captured {rows} entries")

# Open the database and shade one entry: colour by the field, ambient occlusion on top.
db = dr.Database(out / "torus.cdb")
print(db, db.parameters, db.select("phi > 10"))
p = dr.Pipeline()
read = p.add("CinemaReader", database=db.path, entry=db.select("phi=60")[0])
colour = p.add("ColorMapping", channel="wave", colormap="viridis")
ao = p.add("SSAO")
p.connect(read.image, colour.image)
p.connect(colour.image, ao.image)
first = p.evaluate(ao.image)
print("ran", p.last_run)

# Change the colour map: only the colour mapping runs again. SSAO reads depth
# and normals, not colour, so its occlusion is reused around the new colours
# (the evaluator's channel-granular cache).
colour.colormap = "plasma"
second = p.evaluate(ao.image)
print("ran", p.last_run)
assert p.last_run == ["colormapping"]
second.save(str(out / "torus-plasma.png"))
p.save(str(out / "torus.yaml"))
print("wrote", out / "torus-plasma.png", "and", out / "torus.yaml")
