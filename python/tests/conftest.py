"""Shared fixtures: the repository root as working folder and the `rolldyn` program to compare
the package's answers with (env `ROLLDYN_BIN`, default target/release/rolldyn)."""

import json
import os
import subprocess
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
ROLLDYN_BIN = Path(os.environ.get("ROLLDYN_BIN", REPO / "target" / "release" / "rolldyn"))


@pytest.fixture(autouse=True)
def at_repo_root(monkeypatch):
    """Every test runs from the repository root, where the example paths start."""
    monkeypatch.chdir(REPO)


def run_cli(*args: str) -> subprocess.CompletedProcess:
    """Runs the `rolldyn` program; fails the test when it is missing."""
    if not ROLLDYN_BIN.exists():
        pytest.fail(f"{ROLLDYN_BIN} is missing: build it (cargo build --release) or set ROLLDYN_BIN")
    return subprocess.run([str(ROLLDYN_BIN), *args], capture_output=True, text=True, cwd=REPO)


def cli_json(*args: str) -> dict:
    """The JSON answer of `rolldyn <args> --json`."""
    done = run_cli(*args, "--json")
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def is_wall_time(key: str) -> bool:
    """A wall-clock figure of an answer: the only figures that differ between two runs of the
    same input."""
    return "wall" in key or key == "solve_time_s"


def without_wall_times(value):
    """A JSON answer without its wall-clock figures."""
    if isinstance(value, dict):
        return {k: without_wall_times(v) for k, v in value.items() if not is_wall_time(k)}
    if isinstance(value, list):
        return [without_wall_times(v) for v in value]
    return value
