# Capture from arrays and from files: triangles with point and cell fields,
# tubes with radii, spheres, a mesh file through the scene library's
# readers, cameras as a grid or a list; bad arrays refused with the reason.
import numpy as np
import pytest

import darkroom as dr


def quad(z=0.0):
    v = np.array([[-1, -1, z], [1, -1, z], [1, 1, z], [-1, 1, z]], np.float32)
    return v, np.array([[0, 1, 2], [0, 2, 3]])


def test_cell_fields_lines_and_a_camera_list(tmp_path):
    s = dr.Scene()
    v, t = quad()
    s.add_triangles("quad", v, t, cell_fields={"side": [1.0, 2.0]})
    s.add_lines("tube", np.array([[-1, 0, 0.5], [0, 0, 0.5], [1, 0, 0.5]]), radii=[0.05, 0.1, 0.05],
                point_fields={"heat": [0.0, 1.0, 2.0]})
    cams = dr.CameraList([{"position": (0, 0, 5), "target": (0, 0, 0)}, {"position": (0, 0, -5), "target": (0, 0, 0)}],
                         resolution=(64, 48))
    assert dr.capture(s, cams, tmp_path / "c.cdb", ids=True) == 2
    db = dr.Database(tmp_path / "c.cdb")
    assert db.parameters[-1] == "camera" and len(db) == 2
    front = db.read(where="camera=0")
    assert front.shape == (48, 64) and {"side", "heat", "Z"} <= set(front.channels)
    side = front["side"]
    assert set(np.unique(side[np.isfinite(side)])) == {1.0, 2.0}  # each triangle its own value
    heat = front["heat"][24]  # the tube crosses the middle row, hotter towards its middle
    assert np.nanmax(heat) > 0.5 and np.isnan(front["heat"][2, 32])


def test_a_mesh_file_through_the_scene_readers(tmp_path):
    ply = tmp_path / "two.ply"
    ply.write_text("ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                   "property float temp\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                   "-1 -1 0 1\n1 -1 0 2\n1 1 0 3\n-1 1 0 4\n4 0 1 2 3\n")
    s = dr.Scene()
    assert s.add_file(ply) == []
    assert s.object_names == ["two"] and s.field_names == ["temp"]
    dr.capture(s, dr.CameraGrid(resolution=(32, 32), phi=[0], theta=[0], up=(0, 1, 0)), tmp_path / "m.cdb")
    temp = dr.Database(tmp_path / "m.cdb").read()["temp"]
    assert np.nanmin(temp) >= 1 and np.nanmax(temp) <= 4 and np.isfinite(temp).sum() > 100


def test_bad_arrays_and_existing_databases_are_refused(tmp_path):
    s = dr.Scene()
    with pytest.raises(ValueError, match=r"expected an \(n, 3\) array"):
        s.add_points("p", np.zeros((4, 2)))
    v, t = quad()
    with pytest.raises(ValueError, match=r"indices must lie in \[0, 4\)"):
        s.add_triangles("q", v, t + 2)
    with pytest.raises(ValueError, match="expected 4 values"):
        s.add_triangles("q", v, t, point_fields={"f": [1, 2]})
    s.add_triangles("q", v, t)
    with pytest.raises(ValueError, match="already in the scene"):
        s.add_triangles("q", v, t)
    grid = dr.CameraGrid(resolution=(16, 16))
    dr.capture(s, grid, tmp_path / "q.cdb")
    with pytest.raises(dr.Error, match="q.cdb"):
        dr.capture(s, grid, tmp_path / "q.cdb")
    assert dr.capture(s, grid, tmp_path / "q.cdb", resume=True) == 0  # nothing left to do
