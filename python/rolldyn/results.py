"""The results of the rolldyn analyses: the summary as attributes and as a dict, the tables as
pandas DataFrames, the text the command line prints, plots, and an HTML view for notebooks."""

from __future__ import annotations

import html
from typing import Any, Optional

import pandas as pd


class Result:
    """A result: `summary` (the dict `rolldyn <command> --json` prints; SI units, the unit in
    each key's name), its keys also as attributes (``result.cage_slip_mean``), `tables` (name →
    DataFrame, also attributes), and ``str(result)``, the command line's text."""

    def __init__(self, summary: dict, text: str, tables: dict, model=None):
        self.summary = summary
        self.text = text
        self.tables = tables
        self.model = model

    def __getattr__(self, name: str) -> Any:
        if name.startswith("_") or name in ("summary", "tables", "text", "model"):
            raise AttributeError(name)
        if name in self.tables:
            return self.tables[name]
        if isinstance(self.summary, dict) and name in self.summary:
            return self.summary[name]
        keys = self.summary if isinstance(self.summary, dict) else []
        raise AttributeError(
            f"{type(self).__name__} has no {name!r}; summary keys: {', '.join(keys)}"
            + (f"; tables: {', '.join(self.tables)}" if self.tables else "")
        )

    def __getitem__(self, key: str) -> Any:
        return self.summary[key]

    def __contains__(self, key: str) -> bool:
        return key in self.summary

    def __dir__(self):
        keys = set(self.summary) if isinstance(self.summary, dict) else set()
        return sorted(set(super().__dir__()) | keys | set(self.tables))

    def __str__(self) -> str:
        return self.text

    def __repr__(self) -> str:
        items = self.summary.items() if isinstance(self.summary, dict) else []
        figures = ", ".join(
            f"{k}={v!r}" for k, v in list(items)[:4] if not isinstance(v, (dict, list))
        )
        return f"<rolldyn.{type(self).__name__} {figures}…>"

    def _repr_html_(self) -> str:
        items = self.summary.items() if isinstance(self.summary, dict) else []
        rows = "".join(
            f"<tr><th style='text-align:left'>{html.escape(k)}</th>"
            f"<td style='text-align:left'>{html.escape(_short(v))}</td></tr>"
            for k, v in items
        )
        parts = [f"<b>rolldyn.{type(self).__name__}</b>", f"<table>{rows}</table>"]
        for name, table in self.tables.items():
            parts.append(f"<details><summary>table <code>{html.escape(name)}</code>: "
                         f"{len(table)} rows × {len(table.columns)} columns</summary>"
                         f"{table.head(10).to_html()}</details>")
        return "\n".join(parts)


def _short(value: Any) -> str:
    text = repr(value) if not isinstance(value, str) else value
    return text if len(text) <= 120 else text[:117] + "…"


class Run(Result):
    """A dynamics run (`simulate`): the summary, and — with ``tables=True`` — `bearing` (one row
    per output time), `rollers` (one row per roller and output time) and `revolutions` (one row
    per cage revolution) as DataFrames with SI columns (None when not kept)."""

    def __getattr__(self, name: str) -> Any:
        if name in ("bearing", "rollers", "revolutions"):
            return self.tables.get(name)
        return super().__getattr__(name)

    def plot_cage_speed(self, ax=None):
        """Cage speed and the epicyclic (no-slip) cage speed against time."""
        from . import plots

        return plots.cage_speed(self, ax)

    def plot_cage_slip(self, ax=None):
        """Cage slip against time."""
        from . import plots

        return plots.cage_slip(self, ax)

    def plot_cage_orbit(self, ax=None):
        """Cage centre orbit (the cage's whirl in its clearance), µm, to equal aspect, with the
        clearance circle."""
        from . import plots

        return plots.cage_orbit(self, ax)

    def plot_roller_forces(self, ax=None, roller: int = 1):
        """Contact forces of roller `roller` (numbered from 1, as in the tables) against its
        azimuth."""
        from . import plots

        return plots.roller_forces(self, ax, roller)


class Contact(Result):
    """A roller–raceway contact (`contact`): the summary and the pressure map `pressure` [Pa] on
    the cell grid `x` (along the roller) × `y` (rolling direction), m: ``pressure[j, i]`` at
    ``(x[i], y[j])``; None for the Hertz method. The cells are the table `pressure_map`."""

    def _grid(self):
        cells: Optional[pd.DataFrame] = self.tables.get("pressure_map")
        if cells is None or cells.empty:
            return None, None, None
        x = sorted(set(cells["x_m"]))
        y = sorted(set(cells["y_m"]))
        pressure = cells.sort_values(["y_m", "x_m"])["pressure_pa"].to_numpy().reshape(len(y), len(x))
        import numpy as np

        return pressure, np.array(x), np.array(y)

    @property
    def pressure(self):
        return self._grid()[0]

    @property
    def x(self):
        return self._grid()[1]

    @property
    def y(self):
        return self._grid()[2]

    def plot_pressure(self, ax=None):
        """The pressure map, MPa, with its colour bar, to equal aspect."""
        from . import plots

        return plots.pressure_map(self, ax)


class Sweep(Result):
    """A sweep: its summary table `table` (one row per variant: the variant's name, the varied
    model keys, the figures in SI, the error), the names of the varied columns `varied`."""

    def __init__(self, summary: dict, text: str, tables: dict, model=None, table=None):
        super().__init__(summary, text, tables, model)
        if table is not None:
            self.tables["summary"] = table

    @property
    def table(self) -> pd.DataFrame:
        return self.tables["summary"]

    def plot(self, figure: str, ax=None):
        """`figure` (a summary column) against the first numeric varied parameter, or against
        the variant names where no varied parameter is a number."""
        from . import plots

        return plots.sweep_figure(self, figure, ax)
