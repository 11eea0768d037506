"""Sweeps of model variants (`rolldyn sweep`), on this machine or as one Dask task per variant."""

from __future__ import annotations

import json
import math
import os
from pathlib import Path
from typing import Any, Optional, Union

import pandas as pd

from . import _native
from ._core import Progress, call, native
from .results import Sweep


def _toml_value(value: Any) -> str:
    """A TOML value: booleans, numbers, strings (with units), lists."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if not math.isfinite(value):
            raise ValueError(f"sweep table: {value} is not a finite number")
        return repr(value)
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_toml_value(v) for v in value) + "]"
    return json.dumps(str(value), ensure_ascii=False)


def write_sweep_file(
    table: pd.DataFrame,
    path: Union[str, os.PathLike],
    model: Union[str, os.PathLike],
    analysis: str = "simulate",
    **settings: Optional[str],
) -> Path:
    """Writes a sweep file of `table`: one variant per row, named by its ``variant`` column (or
    its index), the other columns dotted model keys (``roller.count``); empty cells leave the
    base `model`'s key alone. `settings`: ``duration``, ``discard``, ``period``, ``method``."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    lines = [
        f"model = {_toml_value(os.path.abspath(model))}",
        f"analysis = {_toml_value(analysis)}",
    ]
    lines += [f"{k} = {_toml_value(v)}" for k, v in settings.items() if v is not None]
    names = table["variant"] if "variant" in table.columns else table.index
    keys = [c for c in table.columns if c != "variant"]
    for name, (_, row) in zip(names, table.iterrows()):
        lines += ["", "[[variant]]", f"name = {_toml_value(str(name))}"]
        for key in keys:
            value = row[key]
            if value is None or (isinstance(value, float) and math.isnan(value)):
                continue
            if hasattr(value, "item"):
                value = value.item()
            lines.append(f"{_toml_value(key)} = {_toml_value(value)}")
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


def _run_shard(sweep_file: str, out: str, shard: int, shards: int, resume: bool) -> str:
    """One Dask task: variant `shard` of `shards` (1-based) of the sweep, stored in
    `out/variants/`; summary.* are left to the collection."""
    request = dict(sweep=sweep_file, out=out, shard=f"{shard}/{shards}", jobs=1,
                   no_collect=True, resume=resume)
    call("sweep", request, Sweep)
    return f"{shard}/{shards}"


def sweep(
    sweep_file_or_table: Union[str, os.PathLike, pd.DataFrame],
    client=None,
    *,
    out: Optional[Union[str, os.PathLike]] = None,
    jobs: Optional[int] = None,
    resume: bool = False,
    report: bool = False,
    model: Optional[Union[str, os.PathLike]] = None,
    analysis: str = "simulate",
    progress: Progress = None,
    **settings: Optional[str],
) -> Sweep:
    """Runs a sweep (`rolldyn sweep`, docs/sweep-format.md) and returns its result.

    Parameters
    ----------
    sweep_file_or_table : path or DataFrame
        A sweep file, or a DataFrame of variants (see `write_sweep_file`; then give the base
        `model`, the `analysis` and its `settings`: ``duration``, ``discard``, ``period``,
        ``method``).
    client : dask.distributed.Client, optional
        Run each variant as one Dask task on that cluster (its workers must see the input
        files and `out` at the same paths: a shared file system, as on a Slurm cluster); the
        summary is then collected here and is the same, bit for bit apart from the wall times,
        as that of `rolldyn sweep` on one machine. Without it the variants run in parallel here.
    out : path, optional
        Output folder, default ``out/<sweep file name>``.
    jobs : int, optional
        Parallel jobs on this machine, default all cores.
    resume : bool
        Skip variants already finished from the same inputs.
    report : bool
        Write ``out/report.html`` at the end.
    progress : bool or callable, optional
        Per finished variant; Ctrl-C starts no new variant (the running ones are stored, so
        ``resume=True`` goes on from there) and raises KeyboardInterrupt.

    Returns
    -------
    Sweep
        `table`: one row per variant — ``variant``, ``index``, one column per varied model key
        (named with its SI unit, e.g. ``operating.radial_load_n``), the figures in SI,
        ``wall_time_s``, ``error``; `varied`: the varied columns; `plot(figure)`.
    """
    if isinstance(sweep_file_or_table, pd.DataFrame):
        if model is None:
            raise ValueError("sweep of a table: give the base model file (model=...)")
        out = Path(out or Path("out") / "sweep")
        path = write_sweep_file(sweep_file_or_table, out / "sweep.toml", model, analysis, **settings)
    else:
        if settings:
            raise TypeError(f"sweep() got unexpected keyword arguments {sorted(settings)} "
                            "(settings are only for a table of variants)")
        path = Path(sweep_file_or_table)
        out = Path(out or Path("out") / path.stem)
    path, out = os.path.abspath(path), os.path.abspath(out)
    if client is None:
        return call("sweep", dict(sweep=path, out=out, jobs=jobs, resume=resume, report=report),
                    Sweep, progress=progress)
    shards = len(native(_native.sweep_variants, path))
    futures = client.map(
        _run_shard, [path] * shards, [out] * shards, range(1, shards + 1), [shards] * shards,
        [resume] * shards, pure=False,
    )
    client.gather(futures)
    return call("sweep", dict(sweep=path, out=out, collect_only=True, report=report), Sweep)


def read_summary(out: Union[str, os.PathLike]) -> pd.DataFrame:
    """The summary table of a sweep output folder (`summary.csv`)."""
    return pd.read_csv(Path(out) / "summary.csv", dtype={"variant": str, "error": str})
