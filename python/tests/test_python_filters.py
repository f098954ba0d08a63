# Passes written in Python: registered node types used from code and from a
# pipeline file, beside native passes; their exceptions as node errors.
import numpy as np
import pytest

import darkroom as dr


@dr.register
class Invert(dr.Filter):
    """1 - colour, by `amount`."""
    type = "TestInvert"
    inputs = [dr.ImageIn("image", channels=["value"]), dr.FloatIn("amount", 1.0, 0.0, 1.0)]
    outputs = [dr.ImageOut("image"), dr.ValueOut("mean", "float")]

    def execute(self, image, amount):
        v = image["value"]
        if amount == 0.5:
            raise ValueError("half is not allowed")
        out = image.with_channels({"value": v + amount * (1 - 2 * v)})
        return {"image": out, "mean": float(out["value"].mean())}


PIPELINE = """darkroom: 1
nodes:
  read:
    type: CinemaReader
    parameters: {{database: {db}, parameters: time=1}}
  invert:
    type: TestInvert
    parameters: {{amount: 1.0}}
  colour:
    type: ColorMapping
    parameters: {{channel: value, colormap: viridis}}
edges:
  - read.image -> invert.image
  - invert.image -> colour.image
"""


def test_a_python_pass_runs_in_a_pipeline_loaded_from_a_file(ramp_db, tmp_path):
    assert "TestInvert" in dr.node_types()
    path = tmp_path / "invert.yaml"
    path.write_text(PIPELINE.format(db=ramp_db.path))
    p = dr.Pipeline.load(path)
    source = ramp_db.read(where="time=1")["value"]
    inverted = p.evaluate("invert.image")
    np.testing.assert_allclose(inverted["value"], 1 - source, atol=1e-6)
    assert p.evaluate("invert.mean") == pytest.approx(float((1 - source).mean()), abs=1e-6)
    assert p.evaluate("colour.image")["R"].shape == source.shape
    # The other channels are the input's planes, shared.
    assert sorted(p.last_run) == ["colour"]
    p["invert"].amount = 0.0
    np.testing.assert_allclose(p.evaluate("invert.image")["value"], source)
    assert p.last_run == ["invert"]


def test_a_python_exception_is_the_nodes_error(ramp_db):
    p = dr.Pipeline()
    read = p.add("CinemaReader", name="read", database=ramp_db.path)
    inv = p.add("TestInvert", name="inv", amount=0.5)
    p.connect(read.image, inv.image)
    with pytest.raises(dr.Error, match="ValueError: half is not allowed") as e:
        p.evaluate(inv.image)
    assert e.value.node == "inv"
    with pytest.raises(dr.Error, match="duplicate filter type 'TestInvert'"):
        dr.register(Invert)
    with pytest.raises(TypeError, match="subclass of darkroom.Filter"):
        dr.register(int)
