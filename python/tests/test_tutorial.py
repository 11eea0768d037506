"""The tutorial (python/examples/tutorial.py) runs from start to end and draws its figures."""

import runpy

from conftest import REPO


def test_the_tutorial_runs(tmp_path, monkeypatch):
    monkeypatch.setenv("ROLLDYN_TUTORIAL_OUT", str(tmp_path))
    runpy.run_path(str(REPO / "python" / "examples" / "tutorial.py"), run_name="__main__")
    for figure in ["cage.svg", "clearance-sweep.svg"]:
        assert (tmp_path / figure).stat().st_size > 1000, figure
    assert (tmp_path / "clearance-sweep" / "summary.csv").exists()
