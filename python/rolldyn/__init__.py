"""rolldyn — roller-bearing dynamics with contact hydrodynamics, wear and cage fatigue.

The analyses of the `rolldyn` program, called in-process: the same inputs (keyword arguments
named like the command's flags, engineering units as text) and the same numbers.

>>> import rolldyn
>>> m = rolldyn.load_model("examples/2002834.toml")
>>> run = rolldyn.simulate(m, duration="2rev")
>>> run.summary["cage_slip_mean"]
"""

from . import _native
from ._commands import InputError, RunError
from .api import (
    Contact,
    Model,
    Run,
    check,
    contact,
    ehl_line,
    fatigue,
    film,
    journal,
    load_model,
    loads,
    report,
    simulate,
    skid,
    traction,
    wear,
)
from .sweep import read_summary, sweep, write_sweep_file

__version__ = _native.version()

__all__ = [
    "Contact",
    "InputError",
    "Model",
    "Run",
    "RunError",
    "check",
    "contact",
    "ehl_line",
    "fatigue",
    "film",
    "journal",
    "load_model",
    "loads",
    "read_summary",
    "report",
    "simulate",
    "skid",
    "sweep",
    "traction",
    "wear",
    "write_sweep_file",
]
