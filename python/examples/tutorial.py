# %% [markdown]
# # rolldyn from Python: bearing 2002834, quasi-static against dynamics, and a small sweep
#
# Run from the repository root (`python python/examples/tutorial.py`), or cell by cell in an
# editor that knows `# %%` cells. The figures go to `out/tutorial/` (or `ROLLDYN_TUTORIAL_OUT`).
# The tests run this file (python/tests/test_tutorial.py), so it never rots.

# %%
import os
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

import rolldyn

out = Path(os.environ.get("ROLLDYN_TUTORIAL_OUT", "out/tutorial"))
out.mkdir(parents=True, exist_ok=True)

# %% [markdown]
# ## The bearing
# The cylindrical roller bearing 2002834 of seed 000 (gas-turbine main shaft): 18 rollers of
# 15 × 11 mm on a 180 mm pitch circle, an inner-land-guided machined cage, 8163 rpm and 1600 N
# rotating with the inner ring. `check` gives the derived quantities.

# %%
model = rolldyn.load_model("examples/2002834.toml")
derived = rolldyn.check(model)
print(model, "—", derived.roller_count, "rollers, pitch diameter",
      round(derived.pitch_diameter_m * 1e3, 1), "mm")
derived  # in a notebook, the result shows itself as a table

# %% [markdown]
# ## Quasi-static skidding (seed 001)
# The cage speed that balances the rollers' traction against the land friction and the drag.

# %%
quasi_static = rolldyn.skid(model)
print(f"quasi-static cage slip {quasi_static.cage_slip:.4f} "
      f"(converged: {quasi_static.converged})")

# %% [markdown]
# ## Dynamics (seed 000)
# Five cage revolutions of the 6-DOF model: rollers, cage and inner ring free, every contact
# intermittent. The summary has the same keys as `rolldyn simulate --json`; the tables are
# pandas DataFrames in SI units.

# %%
run = rolldyn.simulate(model, duration="5rev", progress=True)
print(f"dynamic cage slip {run.cage_slip_mean:.4f} over the steady "
      f"revolutions, largest inner-raceway force {run.max_inner_contact_force_n:.0f} N")
print(run.revolutions[["revolution", "cage_slip_mean", "max_cage_land_force_n"]])

# %% [markdown]
# Both models run the cage slightly faster than the epicyclic speed (negative slip, a fraction of
# the epicyclic speed), but the
# quasi-static slip printed above is several times the dynamic mean: the quasi-static cage sits
# still at the eccentricity where its land friction balances the rollers, while the dynamic cage
# whirls in its land clearance and touches the land only part of the time (the land force of each
# revolution above).

# %%
fig, (orbit, speed) = plt.subplots(1, 2, figsize=(11, 4))
run.plot_cage_orbit(orbit)
run.plot_cage_speed(speed)
speed.axhline(quasi_static.cage_speed_rad_s, color="k", lw=0.8, ls=":", label="quasi-static")
speed.legend()
fig.tight_layout()
fig.savefig(out / "cage.svg")

# %% [markdown]
# ## A small sweep
# The radial clearance at 0, 9 and 30 µm (`examples/2002834/clearance-sweep.toml`). With a
# `dask.distributed.Client` as `client=`, every variant would be one task on that cluster.

# %%
clearance = rolldyn.sweep("examples/2002834/clearance-sweep.toml", out=out / "clearance-sweep")
print(clearance.table[["variant", *clearance.varied, "cage_slip_mean", "max_inner_contact_force_n"]])
fig, ax = plt.subplots(figsize=(5, 3.5))
clearance.plot("cage_slip_mean", ax)  # against the varied clearance, not the variant order
fig.tight_layout()
fig.savefig(out / "clearance-sweep.svg")
