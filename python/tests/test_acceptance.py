# Issue 28's acceptance script, run as written: from a folder beside which
# ../shared/data is the shared data (the project root's situation), so that
# what it writes (tour.yaml, sphere.cdb) lands in a temporary folder.
import os
import pathlib
import runpy


def test_the_acceptance_script_runs_as_written(shared, tmp_path, monkeypatch):
    (tmp_path / "shared").symlink_to(shared.parent)
    work = tmp_path / "root"
    work.mkdir()
    monkeypatch.chdir(work)
    script = pathlib.Path(__file__).with_name("acceptance_script.py")
    runpy.run_path(str(script), run_name="__main__")
    assert (work / "tour.yaml").is_file() and (work / "sphere.cdb" / "data.csv").is_file()
