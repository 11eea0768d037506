"""The rolldyn analyses from Python: one function per `rolldyn` command, the same inputs (keyword
arguments named like the command's flags, engineering units as text: ``speed="8163rpm"``; a
plain number is SI) and the same numbers (the dict `--json` prints)."""

from __future__ import annotations

import json
import os
import tempfile
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable, Optional, Union

import numpy as np
import pandas as pd

from . import _native
from ._commands import answer, flags, model_args, native

PathLike = Union[str, "os.PathLike[str]"]


class Model:
    """A bearing model: a model file (docs/model-format.md) with any overrides applied.

    >>> m = rolldyn.load_model("examples/2002834.toml")
    >>> faster = m.with_overrides({"operating.inner_speed": "10000 rpm"})
    """

    def __init__(self, native_model):
        self._native = native_model

    @property
    def source(self) -> str:
        """The model file (or ``<embedded 2002834.toml>``)."""
        return self._native.source

    @property
    def text(self) -> str:
        """The model's TOML text, overrides applied."""
        return self._native.text

    @property
    def name(self) -> str:
        """The bearing's name."""
        return self._native.name

    def with_overrides(self, overrides: Optional[dict] = None, **keys: Any) -> "Model":
        """A copy with model keys set, as a sweep variant sets them: dotted keys in a dict
        (``{"roller.count": 22}``) or keyword arguments with ``__`` for the dot
        (``roller__count=22``). Values are numbers, strings with units, booleans, lists."""
        merged = dict(overrides or {})
        merged.update({key.replace("__", "."): value for key, value in keys.items()})
        return Model(native(self._native.with_overrides, json.dumps(merged)))

    def __repr__(self) -> str:
        return f"rolldyn.Model({self.name!r} from {self.source!r})"


def load_model(path: Optional[PathLike] = None) -> Model:
    """Loads a model file; the embedded 2002834 model (seed 000) when `path` is None. Bad input
    raises `rolldyn.InputError` with `file`, `line`, `key` and `reason`."""
    return Model(native(_native.load_model, None if path is None else os.fspath(path)))


ModelLike = Union[Model, PathLike, None]
"""A `Model`, a model file, or None for the embedded 2002834."""


def as_model(model: ModelLike) -> Model:
    """The model of a `ModelLike` argument."""
    return model if isinstance(model, Model) else load_model(model)


@dataclass
class Run:
    """A dynamics run: `summary` (the dict of `rolldyn simulate --json`) and its tables —
    `bearing` (one row per output time), `rollers` (one row per roller and output time) and
    `revolutions` (one row per cage revolution) — as pandas DataFrames with SI columns."""

    summary: dict
    bearing: Optional[pd.DataFrame] = None
    rollers: Optional[pd.DataFrame] = None
    revolutions: Optional[pd.DataFrame] = None
    model: Optional[Model] = field(default=None, repr=False)

    def plot_cage_speed(self, ax=None):
        """Cage speed and the epicyclic (no-slip) cage speed against time."""
        from . import plots

        return plots.cage_speed(self, ax)

    def plot_cage_slip(self, ax=None):
        """Cage slip against time."""
        from . import plots

        return plots.cage_slip(self, ax)

    def plot_cage_orbit(self, ax=None):
        """Cage centre orbit (the cage's whirl in its clearance), μm."""
        from . import plots

        return plots.cage_orbit(self, ax)

    def plot_roller_forces(self, ax=None, roller: int = 1):
        """Contact forces of roller `roller` (numbered from 1, as in the tables) against its
        azimuth."""
        from . import plots

        return plots.roller_forces(self, ax, roller)


def _table(raw: bytes, columns: list[str]) -> pd.DataFrame:
    values = np.frombuffer(raw, dtype="<f8").reshape(-1, len(columns))
    return pd.DataFrame(values, columns=columns)


def simulate(
    model: ModelLike = None,
    duration: str = "2rev",
    speed: Optional[str] = None,
    radial_load: Optional[str] = None,
    *,
    tables: bool = True,
    progress: Optional[Callable[[float, float], Any]] = None,
    **options: Any,
) -> Run:
    """Time-domain 6-DOF dynamics (`rolldyn simulate`): `duration` in cage revolutions (``"20rev"``)
    or time (``"0.2s"``); further flags as keyword arguments (``outer_speed``, ``axial_load``,
    ``misalignment``, ``oil_temperature``, ``output_step``, ``tolerance``, ``integrator``,
    ``out``, ``row_offset``, …).

    `progress(fraction, simulated_time_s)` is called every 0.1 s of wall time; the GIL is released
    while the run goes on, and Ctrl-C stops it at its last accepted step (KeyboardInterrupt).
    With `tables` the run keeps its time series in memory (a double-row tapered bearing keeps
    none: give ``out=`` for its table, ``tapered.csv``).
    """
    model = as_model(model)
    args = ["simulate"] + model_args(model) + flags(
        duration=duration, speed=speed, radial_load=radial_load, quiet=True, json=True, **options
    )
    text, raw = native(_native.simulate, args, model._native, tables, progress)
    run = Run(summary=json.loads(text), model=model)
    if raw is not None and len(raw[0]) > 0:
        bearing, rollers, revolutions = _native.table_columns()
        run.bearing = _table(raw[0], bearing)
        run.rollers = _table(raw[1], rollers)
        run.revolutions = _table(raw[2], revolutions)
    return run


def skid(model: ModelLike = None, **options: Any) -> dict:
    """Quasi-static roller and cage skidding (`rolldyn skid`, seed 001): ``speed``,
    ``radial_load`` (one value or a ``"100N..700N:50N"`` sweep), ``outer_speed``,
    ``temperatures``, ``friction``, ``cage_land``, ``out``."""
    return answer(["skid"], as_model(model), **options)


def check(model: ModelLike = None, **options: Any) -> dict:
    """Validates a model and returns its derived quantities (`rolldyn check`)."""
    return answer(["check"], as_model(model), **options)


def loads(model: ModelLike, **options: Any) -> dict:
    """Quasi-static load distribution of a double-row tapered bearing (`rolldyn loads`)."""
    return answer(["loads"], as_model(model), **options)


@dataclass
class Contact:
    """A roller–raceway contact (`rolldyn contact`): `summary` (the `--json` dict) and the
    pressure map `pressure` [Pa] on the cell grid `x` (along the roller) × `y` (rolling
    direction), m: ``pressure[j, i]`` at ``(x[i], y[j])``; None for the Hertz method."""

    summary: dict
    pressure: Optional[np.ndarray]
    x: Optional[np.ndarray]
    y: Optional[np.ndarray]


def contact(model: ModelLike = None, load: Union[str, float] = "1167N", **options: Any) -> Contact:
    """Roller–raceway contact pressure (`rolldyn contact`): ``load``, ``tilt``, ``cells``
    (``"350x9"``), ``method`` (boussinesq, slices, hertz), ``raceway``, ``slice_law``."""
    model = as_model(model)
    with tempfile.TemporaryDirectory() as scratch:
        out = options.pop("out", None) or scratch
        summary = answer(["contact"], model, load=load, out=out, **options)
        path = Path(out) / "pressure_map.csv"
        if not path.exists():
            return Contact(summary, None, None, None)
        cells = pd.read_csv(path)
    x = np.unique(cells["x_m"].to_numpy())
    y = np.unique(cells["y_m"].to_numpy())
    pressure = cells["pressure_pa"].to_numpy().reshape(len(y), len(x))
    return Contact(summary, pressure, x, y)


def traction(**options: Any) -> dict:
    """Muraki thermal EHL traction curve, critical slip and film (`rolldyn traction`): ``oil``,
    ``temperature``, ``max_pressure``, ``rolling_speed``, ``contact``, ``radius``, ``length``,
    ``rheology``, ``temperatures``/``max_pressures`` for families of curves."""
    return answer(["traction"], **options)


def film(**options: Any) -> dict:
    """Central and minimum film, Λ and regime of a contact (`rolldyn film`)."""
    return answer(["film"], **options)


def journal(file: Optional[PathLike] = None, **options: Any) -> dict:
    """Finite journal bearing by the Reynolds equation (`rolldyn journal`), from flags or a
    journal file (``file="examples/journal/seed002-ch4.toml"``)."""
    if file is not None:
        options["file"] = os.fspath(file)
    return answer(["journal"], **options)


def ehl_line(**options: Any) -> dict:
    """Lubricated roller–plate line contact: rigid, piezoviscous or full EHL, load steps
    (`rolldyn ehl-line`)."""
    return answer(["ehl-line"], **options)


def wear(model: ModelLike = None, **options: Any) -> dict:
    """Archard wear over the bearing's life, fed back into the geometry each period
    (`rolldyn wear`): ``life``, ``period``, ``method``, ``pressure``, ``revolutions``, ``out``
    (default ``out/<model>-wear``), …"""
    return answer(["wear"], as_model(model), quiet=True, **options)


def fatigue(model: ModelLike = None, **options: Any) -> dict:
    """Cage high-cycle fatigue (`rolldyn fatigue`): ``stress`` (frame, calculix), ``revolutions``,
    ``misalignment``, ``inclusion``, ``out``, …"""
    return answer(["fatigue"], as_model(model), **options)


def report(folder: PathLike) -> dict:
    """Writes the HTML report of an output folder of `simulate`, `sweep`, `wear` or `fatigue`
    (`rolldyn report`, docs/outputs.md): ``{"report": path of report.html, "kind": …,
    "warnings": [...]}``. ``report=True`` beside ``out=`` in those functions writes it at the end
    of the run."""
    return answer(["report", os.fspath(folder)])
