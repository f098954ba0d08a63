"""Capture from arrays: a Scene of numpy arrays, cameras, and capture() into a
Cinema database, through the in situ API (darkroom/insitu.h) — what a
simulation or a mesh from meshio, VTK or ParaView's Python hands over
without writing a file. The conventions (phi/theta, framing) are those of
scene files (docs/scene-format.md)."""
import math as _math

import numpy as _np

from . import _darkroom


def _vertices(v, what):
    a = _np.ascontiguousarray(v, dtype=_np.float32)
    if a.ndim != 2 or a.shape[1] != 3:
        raise ValueError(f"{what}: expected an (n, 3) array of positions, got shape {a.shape}")
    return a


def _indices(i, columns, what, count):
    a = _np.asarray(i)
    if a.size and (a.min() < 0 or a.max() >= count):
        raise ValueError(f"{what}: indices must lie in [0, {count}), got [{a.min()}, {a.max()}]")
    a = _np.ascontiguousarray(a, dtype=_np.uint32)
    if columns and (a.ndim != 2 or a.shape[1] != columns):
        raise ValueError(f"{what}: expected an (n, {columns}) array of vertex indices, got shape {a.shape}")
    return a


def _values(v, count, what):
    a = _np.ascontiguousarray(v, dtype=_np.float32).reshape(-1)
    if a.size != count:
        raise ValueError(f"{what}: expected {count} values, got {a.size}")
    return a


class Scene:
    """Objects given as numpy arrays (copied once into float32 / uint32 where
    they are of another type, then kept here until the capture is done)."""

    def __init__(self):
        self._objects = []

    def _add(self, kind, name, vertices, primitives, point_fields, cell_fields, **extra):
        if any(o["name"] == name for o in self._objects):
            raise ValueError(f"an object named '{name}' is already in the scene")
        fields = {}
        for f, values in (point_fields or {}).items():
            fields[f] = (_values(values, len(vertices), f"{name}: point field '{f}'"), False)
        for f, values in (cell_fields or {}).items():
            fields[f] = (_values(values, primitives, f"{name}: cell field '{f}'"), True)
        self._objects.append(dict(kind=kind, name=name, vertices=vertices, fields=fields, **extra))

    def add_triangles(self, name, vertices, triangles, point_fields=None, cell_fields=None):
        """A triangle mesh: (n, 3) positions and (m, 3) vertex indices."""
        v = _vertices(vertices, name)
        t = _indices(triangles, 3, f"{name}: triangles", len(v))
        self._add("triangles", name, v, len(t), point_fields, cell_fields, triangles=t)

    def add_lines(self, name, vertices, segments=None, radius=0.01, radii=None, point_fields=None, cell_fields=None):
        """Tubes: segment i joins vertex segments[i] and segments[i] + 1 (the
        default: one polyline through every vertex); one radius, or one per vertex."""
        v = _vertices(vertices, name)
        s = _indices(_np.arange(max(len(v) - 1, 0)) if segments is None else segments, 0,
                     f"{name}: segments", max(len(v) - 1, 0))
        r = None if radii is None else _values(radii, len(v), f"{name}: radii")
        self._add("lines", name, v, len(s), point_fields, cell_fields, segments=s, radii=r, radius=float(radius))

    def add_points(self, name, vertices, radius=0.01, radii=None, point_fields=None):
        """Spheres at (n, 3) positions; one radius, or one per point."""
        v = _vertices(vertices, name)
        r = None if radii is None else _values(radii, len(v), f"{name}: radii")
        self._add("points", name, v, len(v), point_fields, None, radii=r, radius=float(radius))

    def add_file(self, path, name=None, radius=0.01):
        """The geometry of a mesh file Darkroom reads (.ply .obj .off .stl .vtk .vtp
        .vtu .pvtp .pvtu), with its point and cell fields: one object per
        part ("name/surface", "name/lines", "name/points" when there are
        several); lines and points get `radius`. Returns the reader's warnings."""
        import os
        parts, warnings = _darkroom.read_mesh(path)
        stem = name or os.path.splitext(os.path.basename(os.fspath(path)))[0]
        for part in parts:
            object_name = stem if len(parts) == 1 else f"{stem}/{part['representation']}"
            kind = part["representation"]
            if kind == "surface":
                self.add_triangles(object_name, part["positions"], part["indices"], part["point_fields"],
                                   part["cell_fields"])
            elif kind == "lines":
                self.add_lines(object_name, part["positions"], part["indices"].reshape(-1), radius=radius,
                               point_fields=part["point_fields"], cell_fields=part["cell_fields"])
            else:
                self.add_points(object_name, part["positions"], radius=radius, point_fields=part["point_fields"])
        return warnings

    @property
    def object_names(self):
        return [o["name"] for o in self._objects]

    @property
    def field_names(self):
        return sorted({f for o in self._objects for f in o["fields"]})

    def bounds(self):
        """(low, high) corners, radii included."""
        lows, highs = [], []
        for o in self._objects:
            v = o["vertices"]
            if not len(v):
                continue
            pad = 0.0
            if o["kind"] != "triangles":
                pad = float(o["radii"].max()) if o.get("radii") is not None else o["radius"]
            lows.append(v.min(axis=0) - pad)
            highs.append(v.max(axis=0) + pad)
        if not lows:
            return _np.zeros(3), _np.zeros(3)
        return _np.min(lows, axis=0), _np.max(highs, axis=0)

    def _declare(self, session):
        for o in self._objects:
            if o["kind"] == "triangles":
                session.triangles(o["name"], o["vertices"], o["triangles"])
            elif o["kind"] == "lines":
                session.lines(o["name"], o["vertices"], o["segments"], o["radii"], o["radius"])
            else:
                session.points(o["name"], o["vertices"], o["radii"], o["radius"])
            for f, (values, cells) in o["fields"].items():
                session.field(o["name"], f, values, cells)


class CameraGrid:
    """Cinema's phi/theta orbit (docs/scene-format.md): `resolution` (width,
    height), angles in degrees, `fov` vertical degrees; `target` and
    `distance` default to framing the scene's bounding sphere, `up` to +Y."""

    def __init__(self, resolution=(512, 512), phi=(0,), theta=(0,), fov=30.0, target=None, distance=None,
                 up=(0.0, 1.0, 0.0)):
        self.resolution = tuple(int(x) for x in resolution)
        self.phi, self.theta = [float(p) for p in phi], [float(t) for t in theta]
        self.fov, self.target, self.distance, self.up = float(fov), target, distance, up

    def _apply(self, session, scene):
        w, h = self.resolution
        session.set_image(w, h, self.fov, 0.0)
        low, high = scene.bounds()
        centre = (low + high) / 2
        r = max(float(_np.linalg.norm(high - low)) / 2, 1e-6)
        # The narrower of the two fields of view takes the sphere.
        half_v = _math.radians(self.fov) / 2
        half_h = _math.atan(_math.tan(half_v) * w / h)
        distance = self.distance or r / _math.sin(min(half_v, half_h))
        target = centre if self.target is None else _np.asarray(self.target, dtype=float)
        session.orbit([float(x) for x in target], float(distance), [float(x) for x in self.up], self.phi, self.theta)


class CameraList:
    """Cameras by position and target (column `camera` = 0, 1, ...)."""

    def __init__(self, cameras, resolution=(512, 512), fov=30.0):
        self.cameras = [(c["position"], c["target"], c.get("up", (0.0, 1.0, 0.0))) for c in cameras]
        self.resolution, self.fov = tuple(int(x) for x in resolution), float(fov)

    def _apply(self, session, scene):
        session.set_image(self.resolution[0], self.resolution[1], self.fov, 0.0)
        for position, target, up in self.cameras:
            session.add_camera([float(x) for x in position], [float(x) for x in target], [float(x) for x in up])


def capture(scene, cameras, database, overwrite=False, resume=False, fields=None, normals=False, ids=False,
            time=0.0):
    """Ray traces `scene` for every camera into the Cinema database folder
    `database` (atomic, locked, resumable, as `darkroom capture`): depth `Z`,
    the fields asked for (default: every field of the scene), normals and
    object/primitive ids if asked. Returns the number of rows written."""
    if overwrite and resume:
        raise ValueError("overwrite and resume: choose one")
    mode = 1 if overwrite else 2 if resume else 0
    session = _darkroom._Capture(str(database), mode)
    try:
        cameras._apply(session, scene)
        session.request(scene.field_names if fields is None else list(fields), bool(normals), bool(ids), bool(ids))
        session.begin_step(float(time))
        scene._declare(session)
        session.capture()
        rows = session.rows_written()
    except BaseException:
        try:
            session.close()
        except _darkroom.Error:
            pass  # the first error is the one to report
        raise
    session.close()
    return rows
