# Shared fixtures: the shared data folder beside the checkout (tests that
# need it skip, saying so, where it is absent) and a small database written
# here, so most tests need nothing from outside.
import os
import pathlib

import numpy as np
import pytest

import darkroom as dr

# Processes the tests start (scripts, the notebook's kernel) run in other
# folders: the package's path must not be relative to this one.
os.environ["PYTHONPATH"] = os.pathsep.join(os.path.abspath(p) for p in
                                           os.environ.get("PYTHONPATH", "").split(os.pathsep) if p)

SHARED = pathlib.Path(os.environ.get("DARKROOM_SHARED_DATA_DIR",
                                     pathlib.Path(__file__).resolve().parents[3] / "shared" / "data"))


@pytest.fixture
def shared():
    if not SHARED.is_dir():
        pytest.skip(f"{SHARED} is absent")
    return SHARED


@pytest.fixture
def ramp_db(tmp_path):
    """A database of three EXR entries (time = 1, 2, 3) whose 'value' channel
    is a ramp times the time, written by a pipeline of this module."""
    folder = tmp_path / "ramps"
    folder.mkdir()
    rows = ["time,FILE"]
    for t in (1, 2, 3):
        value = np.tile(np.linspace(0, 1, 32, dtype=np.float32), (16, 1)) * t
        dr.Image.from_arrays({"value": value}).save(str(folder / f"t{t}.exr"))
        rows.append(f"{t},t{t}.exr")
    (folder / "data.csv").write_text("\n".join(rows) + "\n")
    return dr.Database(str(folder))
