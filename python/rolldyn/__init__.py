"""rolldyn — roller-bearing dynamics with contact hydrodynamics, wear and cage fatigue.

The analyses of the rolldyn library, called in-process: keyword arguments named like the
command line's flags, quantities as SI numbers or text with units, typed results with their
tables as pandas DataFrames (docs/python.md).

>>> import rolldyn
>>> m = rolldyn.load_model("examples/2002834.toml")
>>> run = rolldyn.simulate(m, duration="2rev")
>>> run.cage_slip_mean
"""

from . import _native
from ._core import InputError, RunError
from .api import (
    Model,
    check,
    contact,
    ehl_line,
    fatigue,
    film,
    journal,
    life,
    load_model,
    loads,
    new_model,
    oils,
    rainflow,
    report,
    simulate,
    skid,
    startup,
    traction,
    wear,
)
from .results import Contact, Result, Run, Sweep
from .sweep import read_summary, sweep, write_sweep_file

__version__ = _native.version()

__all__ = [
    "Contact",
    "InputError",
    "Model",
    "Result",
    "Run",
    "RunError",
    "Sweep",
    "check",
    "contact",
    "ehl_line",
    "fatigue",
    "film",
    "journal",
    "life",
    "load_model",
    "loads",
    "new_model",
    "oils",
    "rainflow",
    "read_summary",
    "report",
    "simulate",
    "skid",
    "startup",
    "sweep",
    "traction",
    "wear",
    "write_sweep_file",
]
