"""The rolldyn analyses from Python: one function per analysis, keyword arguments named like the
command line's flags (``radial_load``, ``oil_temperature``), quantities as numbers in SI units or
as text with their unit (``speed=854.8`` or ``speed="8163 rpm"``), results as objects
(`rolldyn.Result`: summary attributes and dict, tables as DataFrames, plots).

A misspelt keyword is a `TypeError`; bad input an `InputError` naming the file, line and key; a
failed run a `RunError`. Long calls (simulate, sweep, wear, fatigue, startup) show a tqdm
progress bar with ``progress=True`` and stop on Ctrl-C with `KeyboardInterrupt`, keeping what
they wrote; the GIL is released while they run.
"""

from __future__ import annotations

import json
import os
from typing import Any, Optional, Sequence, Union

from . import _native
from ._core import Progress, Quantity, call, native
from .results import Contact, Result, Run

PathLike = Union[str, "os.PathLike[str]"]

OIL = ("oil", "oil_file", "strict")
RIG = ("contact", "radius", "length", "youngs_modulus", "poisson_ratio")
OPERATING = ("speed", "outer_speed", "radial_load", "axial_load", "load_direction",
             "oil_temperature", "misalignment")


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
    """Loads a model file; the embedded 2002834 model (seed 000) when `path` is None.

    Raises
    ------
    InputError
        A bad key, with `file`, `line`, `key` and `reason`.
    """
    return Model(native(_native.load_model, None if path is None else os.fspath(path)))


ModelLike = Union[Model, PathLike, None]
"""A `Model`, a model file, or None for the embedded 2002834."""


def as_model(model: ModelLike) -> Model:
    """The model of a `ModelLike` argument."""
    return model if isinstance(model, Model) else load_model(model)


def film(
    *,
    load: Quantity,
    rolling_speed: Quantity,
    oil: Optional[str] = None,
    oil_file: Optional[PathLike] = None,
    strict: bool = False,
    contact: Optional[str] = None,
    radius: Optional[Quantity] = None,
    length: Optional[Quantity] = None,
    youngs_modulus: Optional[Quantity] = None,
    poisson_ratio: Optional[float] = None,
    temperature: Optional[Quantity] = None,
    roughness: Optional[Sequence[Quantity]] = None,
    formula: Optional[str] = None,
    lambda_: Optional[str] = None,
    starvation: Optional[float] = None,
    grease: bool = False,
) -> Result:
    """Central and minimum film thickness, film parameter Λ and regime of a lubricated contact
    (`rolldyn film`).

    Parameters
    ----------
    load : float or str
        Normal load of the contact, N (``"1 kN"``).
    rolling_speed : float or str
        Rolling (entrainment) speed u, m/s.
    oil : str, optional
        Built-in oil (`rolldyn oils`), default ``"pao1-vg320"``.
    oil_file : path, optional
        User oil file (TOML), instead of `oil`.
    strict : bool
        A temperature outside the oil's range is an error, not a warning.
    contact : {"ball-on-disc", "line"}, optional
        The test contact, default ball on disc.
    radius, length : float or str, optional
        Ball radius (or reduced radius R′ of a line contact), default 9.5 mm; line length,
        default 10 mm.
    youngs_modulus, poisson_ratio : optional
        Elastic data of both bodies, default 210 GPa and 0.3.
    temperature : float or str, optional
        Oil temperature, default 40 °C (K as a number).
    roughness : sequence of float or str, optional
        Ra of the two surfaces.
    formula : str, optional
        ``"auto"``, ``"rigid-piezoviscous"``, ``"piezoviscous-elastic"``, ``"seed001"``,
        ``"pan-hamrock"``, ``"hamrock-dowson"``.
    lambda_ : {"seed000", "tallian"}, optional
        Definition of Λ.
    starvation : float, optional
        Both films multiplied by this factor (1 = flooded).
    grease : bool
        Grease lubrication: starvation factor 0.7.

    Returns
    -------
    Result
        Summary keys: ``oil``, ``central_film_m``, ``min_film_m``, ``lambda``, ``regime``,
        ``formula``, ``g1``, ``g2``, ``thermal_factor_kp``, ``piezoviscous_elastic_condition``.
    """
    options = dict(locals())
    options["lambda"] = options.pop("lambda_")
    return call("film", options, Result, groups={"oil": OIL, "rig": RIG})
