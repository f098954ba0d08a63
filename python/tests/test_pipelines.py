# Pipelines: built in code or loaded from a file, evaluated with the
# evaluator's cache kept between calls (only what an edit touches re-runs),
# saved as a file `darkroom run` reads; errors as Python exceptions.
import numpy as np
import pytest

import darkroom as dr


def shading(db):
    p = dr.Pipeline()
    read = p.add("CinemaReader", name="read", database=db.path, parameters="time=2")
    colour = p.add("ColorMapping", name="colour", channel="value", colormap="viridis")
    p.connect(read.image, colour.image)
    return p, read, colour


def test_only_what_an_edit_touches_runs_again(ramp_db):
    p, read, colour = shading(ramp_db)
    out = p.evaluate(colour.image)
    assert out["R"].shape == (16, 32)
    assert sorted(p.last_run) == ["colour", "read"]
    p.evaluate(colour.image)
    assert p.last_run == []  # all cached
    colour.colormap = "plasma"
    again = p.evaluate(colour.image)
    assert p.last_run == ["colour"]
    assert not np.array_equal(again["R"], out["R"])
    assert colour.colormap == "plasma"
    read.entry = 0
    p.evaluate(colour.image)
    assert sorted(p.last_run) == ["colour", "read"]


def test_a_pipeline_saved_is_a_file_the_runner_reads_and_loads_back(ramp_db, tmp_path):
    p, _, colour = shading(ramp_db)
    first = p.evaluate(colour.image)
    p.save(str(tmp_path / "tour.yaml"))
    q = dr.Pipeline.load(tmp_path / "tour.yaml")
    assert set(q.node_names) == {"read", "colour"}
    assert q["colour"].colormap == "viridis"
    np.testing.assert_array_equal(q.evaluate("colour.image")["G"], first["G"])


def test_value_outputs_rows_and_typed_values(ramp_db):
    p, read, _ = shading(ramp_db)
    row = p.evaluate(read.row)
    assert row["time"] == "2" and row["FILE"].endswith("t2.exr")
    c = p.add("ColorMapping")
    assert c.name == "colormapping"
    assert isinstance(read.image, dr.Port) and str(read.image) == "read.image"


def test_errors_name_the_parameter_the_node_and_the_file(ramp_db, tmp_path):
    p, read, colour = shading(ramp_db)
    with pytest.raises(TypeError, match="node 'colour' input 'channel': expected a str"):
        colour.channel = 3
    with pytest.raises(AttributeError, match=r"has no input 'colourmap' \(did you mean 'colormap'\?\); inputs: image, "):
        colour.colourmap = "viridis"
    with pytest.raises(dr.Error, match="unknown node type 'NoSuchType'; "):
        p.add("NoSuchType")
    with pytest.raises(dr.Error, match=r"unknown node type 'ColorMaping' \(did you mean 'ColorMapping'\?\)"):
        p.add("ColorMaping")
    colour.channel = "nothing"
    with pytest.raises(dr.Error) as e:
        p.evaluate(colour.image)
    assert e.value.node == "colour" and "nothing" in str(e.value)
    bad = tmp_path / "bad.yaml"
    bad.write_text("darkroom: 1\nnodes:\n  a:\n    type: ColorMapping\n    parameters: {gamma: 2}\n")
    with pytest.raises(dr.InputError, match="bad.yaml:5"):
        dr.Pipeline.load(bad)
