"""Sweeps from Python — on this machine and as Dask tasks on a `LocalCluster` — give the summary
table of `rolldyn sweep`, bit for bit apart from the wall times."""

import pandas as pd
import pytest

import rolldyn
from conftest import run_cli

SWEEP = "examples/2002834/clearance-sweep.toml"


def cli_summary(out) -> pd.DataFrame:
    done = run_cli("sweep", SWEEP, "--out", str(out), "--quiet")
    assert done.returncode == 0, done.stderr
    return rolldyn.read_summary(out)


def csv_without_times(out) -> list[str]:
    """The lines of `summary.csv` without their last two fields (wall_time_s, error)."""
    lines = (out / "summary.csv").read_text().splitlines()
    assert lines[0].endswith(",wall_time_s,error")
    return [line.rsplit(",", 2)[0] for line in lines]


def timeless(table: pd.DataFrame) -> pd.DataFrame:
    return table.drop(columns=[c for c in table.columns if "wall" in c])


def test_a_local_sweep_equals_the_command_line(tmp_path):
    result = rolldyn.sweep(SWEEP, out=tmp_path / "python")
    python = result.table
    expected = cli_summary(tmp_path / "cli")
    assert list(python["variant"]) == ["c0", "c9", "c30"]
    assert result.varied == ["clearance.radial_m"]
    assert list(python.columns[:3]) == ["variant", "clearance.radial_m", "index"]
    pd.testing.assert_frame_equal(timeless(python), timeless(expected), check_exact=True)


def test_a_dask_sweep_equals_the_command_line(tmp_path):
    distributed = pytest.importorskip("dask.distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        python = rolldyn.sweep(SWEEP, client=client, out=tmp_path / "dask", report=True).table
    assert (tmp_path / "dask" / "report.html").exists()
    expected = cli_summary(tmp_path / "cli")
    pd.testing.assert_frame_equal(timeless(python), timeless(expected), check_exact=True)
    assert csv_without_times(tmp_path / "dask") == csv_without_times(tmp_path / "cli")


def test_a_table_of_variants_is_a_sweep(tmp_path):
    table = pd.DataFrame({"variant": ["c0", "c9", "c30"],
                          "clearance.radial": ["0 mm", "0.009 mm", "0.03 mm"]})
    python = rolldyn.sweep(table, model="examples/2002834.toml", duration="2rev",
                           out=tmp_path / "t").table
    expected = cli_summary(tmp_path / "cli")
    pd.testing.assert_frame_equal(timeless(python), timeless(expected), check_exact=True)
