# Issue 28's acceptance script, as written there. test_acceptance.py runs it from
# a folder whose ../shared/data is the shared data, as from the project root.
import numpy as np
import darkroom as dr

# A database: its rows, and one entry with numpy views of its channels
db = dr.Database("../shared/data/cinema/ttk_extracts_001.cdb")
assert len(db) > 0 and "object" in db.columns
img = db.read(where="object=000")
z = img["Z"]
assert z.shape == (1024, 1024) and z.dtype == np.float32 and not z.flags.writeable
assert "Elevation" in img.channels

# A pipeline built in code, evaluated, edited, evaluated again: only the edited node re-runs
p = dr.Pipeline()
read = p.add("CinemaReader", name="read", database=db.path, parameters="object=000")
colour = p.add("ColorMapping", name="colour", channel="Elevation", colormap="viridis")
p.connect(read.image, colour.image)
out = p.evaluate(colour.image)
assert out["R"].shape == (1024, 1024)
colour.colormap = "plasma"
out = p.evaluate(colour.image)
assert p.last_run == ["colour"]
rgba = out.to_rgba8()
assert rgba.shape == (1024, 1024, 4) and rgba.dtype == np.uint8
assert out._repr_png_()[:8] == b"\x89PNG\r\n\x1a\n"
p.save("tour.yaml")
assert set(dr.Pipeline.load("tour.yaml").node_names) == {"read", "colour"}

# Capture from numpy arrays: a sphere of triangles with a field, and points as spheres
u, v = np.meshgrid(np.linspace(0, np.pi, 64), np.linspace(0, 2 * np.pi, 128), indexing="ij")
verts = np.stack([np.sin(u) * np.cos(v), np.sin(u) * np.sin(v), np.cos(u)], -1).reshape(-1, 3).astype(np.float32)
i = np.arange(64 * 128).reshape(64, 128)
a, b, c, d = i[:-1, :-1], i[:-1, 1:], i[1:, :-1], i[1:, 1:]
tris = np.concatenate([np.stack([a, b, d], -1).reshape(-1, 3), np.stack([a, d, c], -1).reshape(-1, 3)]).astype(np.int32)
scene = dr.Scene()
scene.add_triangles("sphere", verts, tris, point_fields={"height": verts[:, 2]})
scene.add_points("dots", verts[::50] * 1.2, radius=0.03)
dr.capture(scene, dr.CameraGrid(resolution=(256, 256), phi=[0, 90], theta=[30]), "sphere.cdb", overwrite=True)
s = dr.Database("sphere.cdb")
assert len(s) == 2
g = s.read(where="phi=0")
assert np.isfinite(g["Z"]).sum() > 1000 and "height" in g.channels
