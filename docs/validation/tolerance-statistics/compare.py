#!/usr/bin/env python3
"""Revolution statistics of the 2002834 tolerance study (docs/dynamics-integrator.md,
"Revolution statistics against a tight reference").

Each folder holds the `revolutions.csv` and `summary.json` of
`rolldyn simulate examples/2002834.toml --duration 20rev --tolerance TOL --output-step 1ms --json --out DIR`:
`tTOL` with the default error scales (VelocityErrorScale::ContactFrequency), `oldTOL` with
VelocityErrorScale::SurfaceSpeed (a build with that default), `tsit5-TOL` with the Tsitouras 5(4)
pair (`--integrator tsit5` of commit b964a45; the pair was removed afterwards because it was not
cheaper, see docs/dynamics-integrator.md; every such folder is listed, by tolerance),
`rms-TOL` with Hairer's root-mean-square error norm in place of the maximum norm (a scratch
build of the ninth session; not adopted, because it lies on the same cost–accuracy curve, see
docs/dynamics-integrator.md).
For every per-revolution figure it
prints the mean over revolutions FIRST..20 relative to the τ = 1e-8 reference and, in brackets,
the difference in units of the combined standard error of the two means (|z| ≲ 2: within the
revolution-to-revolution scatter).

usage: compare.py [FIRST_REVOLUTION]   (default 6)
"""
import csv
import json
import math
import os
import statistics as st
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
FIRST = int(sys.argv[1]) if len(sys.argv) > 1 else 6
FIGURES = [
    ("slip", "cage_slip_mean"),
    ("F_i", "max_inner_contact_force_n"),
    ("F_o", "max_outer_contact_force_n"),
    ("bar", "max_roller_cage_force_n"),
    ("land", "max_cage_land_force_n"),
    ("rib", "max_roller_end_rib_force_n"),
    ("v_s", "max_inner_sliding_speed_m_s"),
    ("P_f", "friction_power_mean_w"),
    ("orbit", "cage_orbit_radius_m"),
]


def load(run):
    folder = os.path.join(HERE, run)
    with open(os.path.join(folder, "revolutions.csv")) as f:
        rows = [r for r in csv.DictReader(f) if int(float(r["revolution"])) >= FIRST]
    stats = {}
    for _, key in FIGURES:
        values = [float(r[key]) for r in rows]
        stats[key] = (st.mean(values), st.stdev(values) / math.sqrt(len(values)))
    with open(os.path.join(folder, "summary.json")) as f:
        summary = json.load(f)
    return stats, summary["rhs_evaluations"], len(rows)


def main():
    ref, ref_rhs, n = load("t1e-8")
    print(f"revolutions {FIRST}..20 ({n}); reference τ = 1e-8, {ref_rhs} RHS")
    print("reference: " + "  ".join(f"{s} {ref[k][0]:.4g}±{ref[k][1]:.2g}" for s, k in FIGURES))
    print(f"{'run':10s} {'RHS':>7s} " + " ".join(f"{s:>14s}" for s, _ in FIGURES))
    runs = ["t2e-8", "t1e-7", "t1e-6", "t3e-6", "t1e-5", "t3e-5", "t1e-4"]
    runs += ["old1e-6", "old3e-6", "old1e-5", "old3e-5"]
    rms = [d for d in os.listdir(HERE) if d.startswith("rms-")]
    runs += sorted(rms, key=lambda d: float(d.split("-", 1)[1]))
    tsit5 = [d for d in os.listdir(HERE) if d.startswith("tsit5-")]
    runs += sorted(tsit5, key=lambda d: float(d.split("-", 1)[1]))
    for run in runs:
        stats, rhs, _ = load(run)
        cells = []
        for _, key in FIGURES:
            (m, se), (m0, se0) = stats[key], ref[key]
            z = (m - m0) / math.hypot(se, se0) if se + se0 > 0 else 0.0
            cells.append(f"{100 * (m / m0 - 1):+6.1f}%({z:+5.1f})")
        print(f"{run:10s} {rhs:7d} " + " ".join(f"{c:>14s}" for c in cells))


if __name__ == "__main__":
    main()
