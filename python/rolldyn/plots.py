"""Plots of a `rolldyn.Run` (matplotlib): each helper draws on `ax` (a new figure when None) and
returns the axes."""

from __future__ import annotations

import numpy as np


def _axes(ax):
    if ax is None:
        import matplotlib.pyplot as plt

        _, ax = plt.subplots(figsize=(6, 4))
    return ax


def _needs(table, name: str):
    if table is None:
        raise ValueError(f"this run kept no {name} table (simulate(..., tables=True))")
    return table


def cage_speed(run, ax=None):
    bearing = _needs(run.bearing, "bearing")
    ax = _axes(ax)
    t_ms = bearing["time_s"] * 1e3
    ax.plot(t_ms, bearing["cage_speed_rad_s"], label="cage")
    ax.plot(t_ms, bearing["epicyclic_cage_speed_rad_s"], "--", label="epicyclic (no slip)")
    ax.set(xlabel="time, ms", ylabel="cage speed, rad/s", title="Cage speed")
    ax.legend()
    return ax


def cage_slip(run, ax=None):
    bearing = _needs(run.bearing, "bearing")
    ax = _axes(ax)
    ax.plot(bearing["time_s"] * 1e3, 100 * bearing["cage_slip"])
    ax.set(xlabel="time, ms", ylabel="cage slip, %", title="Cage slip")
    return ax


def cage_orbit(run, ax=None):
    bearing = _needs(run.bearing, "bearing")
    ax = _axes(ax)
    ax.plot(bearing["cage_x_m"] * 1e6, bearing["cage_y_m"] * 1e6, lw=0.8, label="cage centre")
    gap = _cage_land_gap(run)
    if gap is not None:
        angle = np.linspace(0, 2 * np.pi, 361)
        ax.plot(gap * 1e6 * np.cos(angle), gap * 1e6 * np.sin(angle), "k--", lw=0.8,
                label=f"land clearance {gap * 1e6:.0f} µm")
        ax.legend(loc="upper right")
    ax.set(xlabel="x, µm", ylabel="y, µm", title="Cage centre orbit")
    ax.set_aspect("equal", adjustable="datalim")
    return ax


def _cage_land_gap(run):
    """The radial gap of the cage on its guiding land (`check`), m; None without a model or a
    land-guided cage."""
    if run.model is None:
        return None
    from .api import check

    summary = check(run.model).summary
    gap = summary.get("cage_land_radial_gap_m")
    return gap if summary.get("cage_land_guided") and gap else None


def pressure_map(contact, ax=None):
    pressure = contact.pressure
    if pressure is None:
        raise ValueError("this contact has no pressure map (method hertz)")
    ax = _axes(ax)
    x, y = contact.x * 1e3, contact.y * 1e3
    image = ax.pcolormesh(x, y, pressure / 1e6, shading="nearest", cmap="viridis")
    ax.figure.colorbar(image, ax=ax, label="pressure, MPa")
    ax.set(xlabel="x along the roller, mm", ylabel="y rolling direction, mm",
           title="Contact pressure")
    ax.set_aspect("equal", adjustable="box")
    return ax


def sweep_figure(sweep, figure: str, ax=None):
    table = sweep.table
    ax = _axes(ax)
    numeric = [c for c in sweep.summary.get("varied", []) if c in table and
               np.issubdtype(table[c].dtype, np.number)]
    if numeric:
        x = table[numeric[0]]
        order = np.argsort(x.to_numpy())
        ax.plot(x.to_numpy()[order], table[figure].to_numpy()[order], "o-")
        ax.set_xlabel(numeric[0].replace("_", " "))
    else:
        ax.plot(range(len(table)), table[figure], "o")
        ax.set_xticks(range(len(table)), table["variant"], rotation=30, ha="right")
        ax.set_xlabel("variant")
    ax.set(ylabel=figure.replace("_", " "), title=figure.replace("_", " "))
    return ax


def roller_forces(run, ax=None, roller: int = 1):
    rollers = _needs(run.rollers, "rollers")
    ax = _axes(ax)
    one = rollers[rollers["roller"] == roller]
    if one.empty:
        raise ValueError(f"no roller {roller}: rollers are numbered 1 to {int(rollers['roller'].max())}")
    azimuth = np.degrees(np.mod(one["azimuth_rad"], 2 * np.pi))
    for column, label in [
        ("inner_force_n", "inner raceway"),
        ("outer_force_n", "outer raceway"),
        ("cage_bar_force_n", "cage bars"),
    ]:
        ax.plot(azimuth, one[column], ".", ms=2, label=label)
    ax.set(xlabel="azimuth, °", ylabel="force, N", title=f"Roller {roller} contact forces")
    ax.legend()
    return ax
