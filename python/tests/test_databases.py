# Databases: every kind the runner reads, rows chosen with --where's syntax or
# SQL, an entry read by the CinemaReader node.
import numpy as np
import pytest

import darkroom as dr


def test_rows_and_entries_of_a_database(ramp_db):
    assert len(ramp_db) == 3 and ramp_db.columns == ["time", "FILE"]
    assert ramp_db.parameters == ["time"] and ramp_db.files == ["FILE"]
    assert ramp_db.row(1) == {"time": "2", "FILE": "t2.exr"}
    assert ramp_db.select("time=2") == [1]
    assert ramp_db.select("time > 1") == [1, 2]
    assert ramp_db.select() == [0, 1, 2]
    assert ramp_db.read(where="time=3")["value"][0, -1] == pytest.approx(3.0)
    assert ramp_db.read(entry=0)["value"][0, -1] == pytest.approx(1.0)
    with pytest.raises(IndexError):
        ramp_db.row(3)


def test_a_bad_entry_is_the_readers_error_naming_the_database(ramp_db):
    with pytest.raises(dr.Error, match="entry 7 is past the last row") as e:
        ramp_db.read(entry=7)
    assert e.value.node == "Database.read"
    with pytest.raises(dr.Error, match="ramps-missing': no such file or directory"):
        dr.Database(ramp_db.path + "-missing")


def test_a_composable_image_set_written_by_ttk(shared):
    db = dr.Database(str(shared / "cinema/ttk_extracts_001.cdb"))
    assert len(db) > 0 and "object" in db.columns
    img = db.read(where="object=000")
    z = img["Z"]
    assert z.shape == (1024, 1024) and z.dtype == np.float32 and not z.flags.writeable
    assert "Elevation" in img.channels


def test_a_database_written_from_python_reads_back_and_resumes(tmp_path):
    path = str(tmp_path / "made.cdb")
    img = lambda t: dr.Image.from_arrays({"value": np.full((4, 5), t, np.float32)})
    with dr.DatabaseWriter(path, ["time", "kind"]) as w:
        w.add({"time": 0.5, "kind": "a"}, img(0.5))
        w.add({"time": 1.5, "kind": "a"}, img(1.5))
    db = dr.Database(path)
    assert len(db) == 2 and db.parameters == ["time", "kind"]
    assert db.read(where="time=1.5")["value"][0, 0] == 1.5
    # An existing database is refused unless overwritten or resumed; a resume keeps what is there.
    with pytest.raises(dr.Error, match="exists"):
        dr.DatabaseWriter(path, ["time", "kind"])
    with dr.DatabaseWriter(path, ["time", "kind"], mode="resume") as w:
        assert w.has({"time": 0.5, "kind": "a"})
        w.add({"time": 2.5, "kind": "b"}, img(2.5))
    assert len(dr.Database(path)) == 3
    with pytest.raises(dr.Error, match="finished"):
        w.add({"time": 3.5, "kind": "b"}, img(3.5))
    with pytest.raises(ValueError, match="mode: expected"):
        dr.DatabaseWriter(path, ["time"], mode="append")
