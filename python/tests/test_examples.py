# The examples of examples/python run as a user runs them: the scripts with
# this interpreter, the notebook through a Jupyter kernel (nbclient), each in
# a folder of its own; the notebook's pictures must come out as PNG.
import os
import pathlib
import subprocess
import sys

import nbclient
import nbformat

EXAMPLES = pathlib.Path(__file__).resolve().parents[2] / "examples" / "python"


def run(script, folder):
    done = subprocess.run([sys.executable, str(EXAMPLES / script), str(folder)], capture_output=True, text=True,
                          timeout=300)
    assert done.returncode == 0, done.stdout + done.stderr
    return done.stdout


def test_the_tour_script(tmp_path):
    out = run("tour.py", tmp_path)
    assert "ran ['colormapping']" in out
    assert (tmp_path / "torus-plasma.png").stat().st_size > 1000 and (tmp_path / "torus.yaml").is_file()


def test_a_mesh_through_meshio(tmp_path):
    out = run("capture_meshio.py", tmp_path)
    assert "8930 triangles" in out and (tmp_path / "bumpy.png").is_file()


def test_the_notebook_runs_and_shows_pictures(tmp_path):
    nb = nbformat.read(str(EXAMPLES / "tour.ipynb"), as_version=4)
    nbclient.NotebookClient(nb, timeout=300, kernel_name="python3",
                            resources={"metadata": {"path": str(tmp_path)}}).execute()
    pictures = [o for c in nb.cells if c.cell_type == "code" for o in c.get("outputs", [])
                if "image/png" in o.get("data", {})]
    assert len(pictures) == 3  # the entry, the shaded entry, the same with the new colour map
    assert (tmp_path / "torus.yaml").is_file()
