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
    ax.plot(bearing["cage_x_m"] * 1e6, bearing["cage_y_m"] * 1e6, lw=0.8)
    ax.set(xlabel="x, µm", ylabel="y, µm", title="Cage centre orbit")
    ax.set_aspect("equal", adjustable="datalim")
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
