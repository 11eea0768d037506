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


def new_model(
    designation: Optional[str] = None,
    *,
    bore: Optional[Quantity] = None,
    outside: Optional[Quantity] = None,
    width: Optional[Quantity] = None,
    type_: Optional[str] = None,
    roller_diameter: Optional[Quantity] = None,
    roller_length: Optional[Quantity] = None,
    rollers: Optional[int] = None,
    cage: Optional[str] = None,
    clearance_group: Optional[str] = None,
    oil: Optional[str] = None,
    name: Optional[str] = None,
    speed: Optional[Quantity] = None,
    radial_load: Optional[Quantity] = None,
    oil_temperature: Optional[Quantity] = None,
    out: Optional[PathLike] = None,
) -> Result:
    """A cylindrical roller bearing model from an ISO designation or its boundary dimensions
    (`rolldyn new`; rules and sources: docs/theory.md §14).

    Parameters
    ----------
    designation : str, optional
        ``"NU2215"``, ``"NJ 310"``, ``"N1012"``, ``"NUP2310"`` (series 10, 2, 22, 3, 23; bores
        20–200 mm). Give it or `bore`, `outside` and `width`.
    bore, outside, width : float or str, optional
        The boundary form: d, D, B (m as numbers, ``"75 mm"``).
    type_ : {"NU", "NJ", "NUP", "N"}, optional
        Boundary form: which rings have ribs, default NU.
    roller_diameter, roller_length : float or str, optional
        The catalogue's D_w, L_w (else the design rules).
    rollers : int, optional
        The catalogue's roller count (else the cage bar rule).
    cage : {"brass", "steel", "peek", "pa66"}, optional
        Cage material, default brass (``cuzn40pb2``).
    clearance_group : {"C2", "CN", "C3", "C4"}, optional
        ISO 5753-1 group, default CN.
    oil : str, optional
        Built-in oil; without it ``"iso-vg-68-mineral"`` is written marked ASSUMED, with a
        `UserWarning`.
    name : str, optional
        ``bearing.name`` of the model.
    speed, radial_load, oil_temperature : float or str, optional
        Written as ``[operating]`` (speed and load together; oil temperature 70 °C marked
        ASSUMED, with a `UserWarning`, when not given).
    out : path, optional
        Write the model file here.

    Returns
    -------
    Result
        Summary keys: ``name``, ``toml`` (the model file's text), ``file``, ``bore_m``,
        ``outside_diameter_m``, ``width_m``, ``roller_diameter_m``, ``roller_length_m``,
        ``rollers``, ``pitch_diameter_m``, ``radial_clearance_m``, ``cage_material``, ``oil``,
        ``warnings``. ``rolldyn.load_model(result.file)`` loads a written model.
    """
    options = dict(locals())
    options["type"] = options.pop("type_")
    if out is not None:
        options["out"] = os.fspath(out)
    return call("new", options, Result)


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


def check(model: ModelLike = None, *, speed: Optional[Quantity] = None,
          outer_speed: Optional[Quantity] = None) -> Result:
    """Validates a model and gives its derived quantities (`rolldyn check`): geometry,
    clearances, masses, the cage pocket and its plays, epicyclic speeds.

    Parameters
    ----------
    model : Model, path or None
        The bearing model; None is the embedded 2002834.
    speed, outer_speed : float or str, optional
        Ring speeds for the epicyclic speeds (rad/s as numbers), default the model's.

    Returns
    -------
    Result
        Summary keys: ``name``, ``kind``, ``roller_diameter_m``, ``roller_length_m``,
        ``effective_contact_length_m``, ``crown_radius_m``, ``slices``, ``roller``,
        ``roller_count``, ``pitch_diameter_m``, ``geometric_clearance_m``,
        ``radial_clearance_m``, ``roller_rib_axial_clearance_m``, ``misalignment_rad``,
        ``inner_ring``, ``outer_ring``, ``cage``, ``cage_land_diameter_m``,
        ``cage_pocket``, ``cage_pocket_play_per_side_m``,
        ``cage_pocket_closing_displacement_m``, ``cage_land_radial_gap_m``,
        ``cage_land_guided``, ``inner_speed_rad_s``, ``outer_speed_rad_s``,
        ``epicyclic_cage_speed_rad_s``, ``epicyclic_roller_speed_rad_s``, ``design_notes``
        (list of ``{"key", "text"}``: findings a designer should look at, e.g. a stated
        clearance other than the raceway diameters imply).
    """
    model = as_model(model)
    return call("check", dict(speed=speed, outer_speed=outer_speed), Result, model=model)


def contact(model: ModelLike = None, *, load: Quantity = "1167N", tilt: Optional[Quantity] = None,
            cells: Optional[str] = None, width: Optional[Quantity] = None,
            method: Optional[str] = None, raceway: Optional[str] = None,
            slice_law: Optional[str] = None, out: Optional[PathLike] = None) -> Contact:
    """Roller–raceway contact pressure (`rolldyn contact`): Boussinesq solver, slice model or
    Hertz.

    Parameters
    ----------
    model : Model, path or None
        The bearing whose roller and raceway are pressed together.
    load : float or str
        Roller load, N.
    tilt : float or str, optional
        Roller tilt relative to the raceway (rad as a number; ``"4arcmin"``).
    cells : str, optional
        Boussinesq grid, cells along the roller × across (``"350x9"``).
    width : float or str, optional
        Transverse extent of the Boussinesq grid.
    method : {"boussinesq", "slices", "hertz"}, optional
    raceway : {"inner", "outer"}, optional
    slice_law : str, optional
        Slice law of the slice method.
    out : path, optional
        Folder for the pressure map and central line (CSV) and the map's plot.

    Returns
    -------
    Contact
        `pressure`, `x`, `y` (the map as a 2-D array), tables ``pressure_map`` and
        ``central_line``; summary keys: ``model``, ``method``, ``load_n``, ``tilt_rad``,
        ``cells``, ``approach_m``, ``max_pressure_pa``, ``mid_pressure_pa``,
        ``mean_pressure_pa``, ``concentration_factor``, ``contact_length_m``,
        ``max_half_width_m``, ``cells_in_contact``, ``iterations``, ``converged``,
        ``solve_time_s``.
    """
    model = as_model(model)
    options = dict(load=load, tilt=tilt, cells=cells, width=width, method=method,
                   raceway=raceway, slice_law=slice_law, out=out)
    return call("contact", options, Contact, model=model)


def oils(*, temperature: Optional[Quantity] = None, oil_file: Optional[PathLike] = None) -> Result:
    """The lubricant library with each oil's properties at `temperature` (`rolldyn oils`).

    The seeds' oils, the ISO VG grades 10…680 as ``iso-vg-<N>-mineral`` / ``iso-vg-<N>-pao``,
    ``mil-prf-23699``, ``mil-prf-7808`` and ``vg220-gear``; each row says which properties are
    measured and which estimated, with the source of each (docs/lubricants.md).

    Parameters
    ----------
    temperature : float or str, optional
        Default 40 °C (K as a number).
    oil_file : path, optional
        Also list a user oil file (TOML; values with units such as ``"870 kg/m3"``).

    Returns
    -------
    Result
        Table ``oils`` (one row per oil); the summary is the list of rows, one dict per oil,
        with the properties at `temperature` (SI), ``class``, ``nu40_m2_s``, ``nu100_m2_s``,
        ``viscosity_index``, ``measured``, ``estimated``, ``provenance`` and ``missing``.
    """
    return call("oils", dict(temperature=temperature, oil_file=oil_file), Result)


def traction(
    *,
    oil: Optional[str] = None,
    oil_file: Optional[PathLike] = None,
    strict: bool = False,
    contact: Optional[str] = None,
    radius: Optional[Quantity] = None,
    length: Optional[Quantity] = None,
    youngs_modulus: Optional[Quantity] = None,
    poisson_ratio: Optional[float] = None,
    temperature: Union[Quantity, Sequence[Quantity], None] = None,
    max_pressure: Union[Quantity, Sequence[Quantity], None] = None,
    rolling_speed: Optional[Quantity] = None,
    slip_max: Optional[float] = None,
    points: Optional[int] = None,
    rheology: Optional[str] = None,
    out: Optional[PathLike] = None,
) -> Result:
    """Muraki thermal EHL traction curve, critical slip (scuffing criterion) and film of a
    lubricated contact (`rolldyn traction`); a list of temperatures or maximum pressures gives
    a family of curves.

    Parameters
    ----------
    oil, oil_file, strict, contact, radius, length, youngs_modulus, poisson_ratio
        The oil and the test contact, as in `film`.
    temperature : float, str or a sequence of them, optional
        Default 40 °C.
    max_pressure : float, str or a sequence of them, optional
        Maximum Hertz pressure, default 1 GPa.
    rolling_speed : float or str, optional
    slip_max : float, optional
        Largest slide-to-roll ratio of the curve.
    points : int, optional
        Points of the curve.
    rheology : {"visco-elastic", "isothermal", "linear-elastic"}, optional
    out : path, optional
        Folder for the curves (CSV) and their plot.

    Returns
    -------
    Result
        Tables ``traction`` (the curves) and ``cases``; summary keys: ``oil``,
        ``rheology``, ``temperature_k``, ``max_pressure_pa``, ``load_n``,
        ``rolling_speed_m_s``, ``critical_slip``, ``max_traction``,
        ``no_maximum_reason``, ``film_thickness_m``, ``lambda``, ``warnings``,
        ``curve``, ``cases``.
    """
    options = dict(locals())
    for key in ("temperature", "max_pressure"):
        if options[key] is not None and not isinstance(options[key], (list, tuple)):
            options[key] = [options[key]]
    return call("traction", options, Result, groups={"oil": OIL, "rig": RIG})


def report(folder: PathLike) -> Result:
    """Writes the HTML report of an output folder of `simulate`, `sweep`, `wear` or `fatigue`
    (`rolldyn report`, docs/outputs.md).

    Returns
    -------
    Result
        Summary keys: ``report``, ``kind``, ``warnings``, ``findings``.
    """
    return call("report", dict(dir=folder), Result)


def skid(model: ModelLike = None, *, speed=None, outer_speed=None, radial_load=None,
         temperatures=None, friction: Optional[str] = None, cage_land: Optional[str] = None,
         out: Optional[PathLike] = None) -> Result:
    """Quasi-static roller and cage skidding (`rolldyn skid`, seed 001), at one point or over a
    range of speed or load.

    Parameters
    ----------
    model : Model, path or None
    speed, outer_speed, radial_load : float, str or range, optional
        One value (``"4000rpm"``) or a range ``"100N..700N:50N"`` (one of them).
    temperatures : str, optional
        Part temperatures.
    friction : {"muraki", "seed001"}, optional
    cage_land : {"finite", "short"}, optional
    out : path, optional

    Returns
    -------
    Result
        Summary keys: ``kinematic_case``, ``inner_speed_rad_s``, ``outer_speed_rad_s``,
        ``radial_load_n``, ``misalignment_rad``, ``cage_speed_rad_s``,
        ``epicyclic_cage_speed_rad_s``, ``cage_slip``, ``roller_slip_reference``,
        ``rollers``, ``max_roller_load_n``, ``max_contact_pressure_pa``,
        ``loaded_rollers``, ``load_zone_half_angle_rad``, ``ring_displacement_m``,
        ``operating_clearance_m``, ``operating_geometry``, ``cage``, ``power_loss_w``,
        ``power_input_w``, ``power``, ``min_scuffing_margin``, ``static_load_rating_n``,
        ``solve_time_s``, ``iterations``, ``converged``, ``residuals``,
        ``friction_model``, ``cage_land_model``, ``cage_drag_law``, ``warnings``; a
        range gives the table of its points, the varied variable
        first.
    """
    model = as_model(model)
    options = dict(speed=speed, outer_speed=outer_speed, radial_load=radial_load,
                   temperatures=temperatures, friction=friction, cage_land=cage_land, out=out)
    return call("skid", options, Result, model=model)


def loads(model: ModelLike, *, speed=None, outer_speed=None, radial_load=None, axial_load=None,
          load_direction: Optional[str] = None, oil_temperature=None, misalignment=None,
          moment=None, row_offset: Optional[float] = None,
          out: Optional[PathLike] = None) -> Result:
    """Quasi-static load distribution of a double-row tapered bearing (`rolldyn loads`): roller
    and rib loads and load zones per row.

    Parameters
    ----------
    model : Model or path
        A double-row tapered bearing.
    speed, outer_speed, radial_load, axial_load, load_direction, oil_temperature, misalignment
        Overrides of the model's operating point.
    moment : float or str, optional
        Tilting moment, N·m.
    row_offset : float, optional
    out : path, optional

    Returns
    -------
    Result
        Summary keys: ``model``, ``radial_load_n``, ``axial_load_n``,
        ``inner_speed_rad_s``, ``misalignment_rad``, ``result``.
    """
    model = as_model(model)
    options = dict(locals())
    options.pop("model")
    return call("loads", options, Result, model=model, groups={"operating": OPERATING})


def life(model: ModelLike, *, speed=None, outer_speed=None, radial_load=None, axial_load=None,
         load_direction: Optional[str] = None, oil_temperature=None, misalignment=None,
         clearance=None, contamination: Optional[str] = None,
         contamination_factor: Optional[float] = None, reliability: Optional[float] = None,
         viscosity=None, duty: Optional[Sequence[dict]] = None) -> Result:
    """Rating life of a cylindrical or double-row tapered bearing (`rolldyn life`): ISO 281
    C_r, L10 and L_nm, ISO 76 C0r and s0, ISO/TS 16281 L10r of each ring and the bearing from
    the slice loads of the load distribution; a duty cycle combined by Palmgren–Miner.

    Parameters
    ----------
    model : Model or path
        A cylindrical or double-row tapered bearing with a ``[lubricant]``.
    speed, outer_speed, radial_load, axial_load, load_direction, oil_temperature, misalignment
        Overrides of the model's operating point (floats SI, or strings with units).
    clearance : float or str, optional
        Diametral operating clearance of a cylindrical bearing (replaces the derived one), m.
    contamination : str, optional
        ISO 281 Table 13 level: ``"extreme-cleanliness"``, ``"high-cleanliness"``,
        ``"normal-cleanliness"`` (the default, named in ``defaults``),
        ``"slight-contamination"``, ``"typical-contamination"``, ``"severe-contamination"``,
        ``"very-severe-contamination"``; e_C is the low end of the level's range.
    contamination_factor : float, optional
        e_C (0…1) given directly instead of a level.
    reliability : float, optional
        Reliability in % from ISO 281 Table 12 (default 90, named in ``defaults``).
    viscosity : float or str, optional
        Kinematic viscosity at the operating temperature, m²/s (replaces the model oil's).
    duty : list of dict, optional
        Duty-cycle rows ``{"time": 0.3, "speed": "5000 rpm", "radial_load": "15 kN"}`` (keys
        ``time`` — a share or hours —, ``speed``, ``radial_load``, ``axial_load``,
        ``oil_temperature``); each row's lives are combined by Palmgren–Miner.

    Returns
    -------
    Result
        Summary keys: ``model``, ``kind``, ``ratings`` (``dynamic_n`` C_r, ``static_n`` C0r,
        ``fatigue_limit_n`` C_u, ``fc``, the dimensions, the lamina ratings),
        ``reliability_percent``, ``a1``, ``contamination``, ``e_c``, ``oil``, ``defaults``,
        ``s0``, ``lives`` (``l10_rev``, ``l10_h``, ``l_nm_rev``, ``l_nm_h``, ``l10r_rev``,
        ``l10r_h``: of the only condition or the duty cycle), ``conditions`` (per row: loads,
        ``equivalent_load``, ``s0``, ``l10_*``, ``viscosity_m2_s``, ``nu1_m2_s``, ``kappa``,
        ``a_iso``, ``l_nm_*``, ``clearance_m``, ``misalignment_rad``, ``l10r_inner_rev``,
        ``l10r_outer_rev``, ``l10r_*``). Tables ``conditions`` and ``slices`` (lamina loads).
    """
    model = as_model(model)
    options = dict(locals())
    options.pop("model")
    options["duty"] = list(duty or [])
    return call("life", options, Result, model=model, groups={"operating": OPERATING})


def journal(*, file: Optional[PathLike] = None, radius=None, length=None, clearance=None,
            viscosity=None, speed=None, eccentricity: Optional[float] = None, load=None,
            temperature=None, cavitation: Optional[str] = None, grid: Optional[str] = None,
            film_start: Optional[str] = None, no_coefficients: bool = False,
            out: Optional[PathLike] = None) -> Result:
    """Finite journal bearing by the Reynolds equation (`rolldyn journal`): load, attitude,
    friction, stiffness and damping, from keyword arguments or a journal file.

    Parameters
    ----------
    file : path, optional
        A journal file (examples/journal/), instead of the geometry arguments.
    radius, length, clearance, viscosity, speed : float or str
    eccentricity : float, optional
        Eccentricity ratio (or give `load`).
    load : float or str, optional
    temperature : float or str, optional
    cavitation : {"reynolds", "jfo", "none"}, optional
    grid : str, optional
        ``"72x24"``.
    film_start : {"max-gap", "free"}, optional
    no_coefficients : bool
        Skip the stiffness and damping coefficients.
    out : path, optional

    Returns
    -------
    Result
        Summary keys: ``attitude_deg``, ``cavitation``, ``converged``,
        ``coupling_iterations``, ``damping_ns_per_m``, ``eccentricity``,
        ``elastic_liner``, ``film_start``, ``friction_torque_nm``,
        ``friction_variable``, ``grid``, ``iterations``, ``limits``,
        ``load_iterations``, ``load_n``, ``max_deflection_m``, ``max_pressure_pa``,
        ``max_temperature_k``, ``mean_temperature_k``, ``min_film_m``, ``power_loss_w``,
        ``side_flow_m3_s``, ``solve_time_s``, ``sommerfeld``, ``stiffness_n_per_m``,
        ``thermal``, ``viscosity_law``.
    """
    return call("journal", dict(locals()), Result)


def ehl_line(*, radius, viscosity, rolling_speed, min_film=None, load_per_length=None,
             piezo=None, law: Optional[str] = None, density: Optional[str] = None,
             elastic: Optional[str] = None, modulus=None, poisson: Optional[float] = None,
             squeeze_velocity=None, nodes: Optional[int] = None, step_to=None, duration=None,
             contact_length=None, mass=None, out: Optional[PathLike] = None) -> Result:
    """Lubricated roller–plate line contact: rigid, piezoviscous or full EHL, and load steps
    (`rolldyn ehl-line`).

    Parameters
    ----------
    radius, viscosity, rolling_speed : float or str
    min_film, load_per_length : float or str, optional
        The film (or the load) to solve for.
    piezo : float or str, optional
        Pressure–viscosity coefficient α.
    law : {"barus", "roelands"}, optional
    density : {"incompressible", "dowson-higginson"}, optional
    elastic : str, optional
    modulus, poisson : optional
    squeeze_velocity, nodes, step_to, duration, contact_length, mass : optional
        The transient load step.
    out : path, optional

    Returns
    -------
    Result
        Summary keys: ``central_film_m``, ``converged``, ``damping_ns_per_m2``,
        ``elastic``, ``hertz_half_width_m``, ``hertz_pressure_pa``, ``iterations``,
        ``limits``, ``load_per_length_n_per_m``, ``max_pressure_pa``, ``min_film_m``,
        ``outlet_position_m``, ``piezo_per_pa``, ``rigid_approach_m``, ``solve_time_s``,
        ``squeeze_velocity_m_s``, ``sum_speed_m_s``, ``transient``.
    """
    return call("ehl-line", dict(locals()), Result)


def simulate(
    model: ModelLike = None,
    *,
    duration: Union[str, float] = "2rev",
    speed: Optional[Quantity] = None,
    outer_speed: Optional[Quantity] = None,
    radial_load: Optional[Quantity] = None,
    axial_load: Optional[Quantity] = None,
    load_direction: Optional[str] = None,
    oil_temperature: Optional[Quantity] = None,
    misalignment: Optional[Quantity] = None,
    output_step: Optional[Quantity] = None,
    max_output: Optional[str] = None,
    tolerance: Optional[float] = None,
    integrator: Optional[str] = None,
    checkpoint: Optional[PathLike] = None,
    checkpoint_interval: Optional[Union[str, float]] = None,
    resume: Optional[PathLike] = None,
    out: Optional[PathLike] = None,
    report: bool = False,
    cage_loads: Optional[PathLike] = None,
    row_offset: Optional[float] = None,
    tables: bool = True,
    progress: Progress = None,
) -> Run:
    """Time-domain 6-DOF dynamics of the bearing (`rolldyn simulate`).

    Parameters
    ----------
    model : Model, path or None
        The bearing model; None is the embedded 2002834.
    duration : str or float
        Cage revolutions (``"20rev"``) or a time (``"0.2s"``; seconds as a number).
    speed, outer_speed, radial_load, axial_load, load_direction, oil_temperature, misalignment
        Overrides of the model's operating point (SI numbers or text with units).
    output_step : float or str, optional
        Sampling step of the tables, default 0.05 ms.
    max_output : str, optional
        Largest size of the output folder (``"2GB"``).
    tolerance : float, optional
        Relative error tolerance of the integrator.
    integrator : {"dopri5", "rosenbrock-w"}, optional
    checkpoint, checkpoint_interval, resume : optional
        Write a checkpoint file every interval; resume from one.
    out : path, optional
        Output folder (tables as CSV and Parquet, plots, run.json).
    report : bool
        Write ``out/report.html`` at the end.
    cage_loads : path, optional
        Export the cage loads of one steady revolution (for `fatigue`).
    row_offset : float, optional
        Second row of a double-row tapered bearing.
    tables : bool
        Keep the time series in memory as DataFrames (`bearing`, `rollers`, `revolutions`; a
        double-row tapered bearing keeps none: give `out`).
    progress : bool or callable, optional
        True shows a tqdm bar; a function is called as ``progress(fraction, simulated_time_s)``
        every 0.1 s. Ctrl-C (or an exception in `progress`) stops the run at its last accepted
        step and raises KeyboardInterrupt (or that exception).

    Returns
    -------
    Run
        Tables ``bearing``, ``rollers``, ``revolutions``; summary keys:
        ``cage_orbit_radius_m``, ``cage_slip_mean``, ``cage_speed_mean_rad_s``,
        ``epicyclic_cage_speed_rad_s``, ``max_cage_land_force_n``,
        ``max_inner_contact_force_n``, ``max_inner_sliding_axial_m_s``,
        ``max_inner_sliding_axial_most_loaded_m_s``,
        ``max_inner_sliding_rolling_direction_m_s``,
        ``max_inner_sliding_rolling_direction_most_loaded_m_s``,
        ``max_inner_sliding_speed_m_s``, ``max_outer_contact_force_n``,
        ``max_relative_slip``, ``max_roller_cage_force_n``,
        ``max_roller_end_cage_force_n``, ``max_roller_end_rib_force_n``,
        ``min_scuffing_margin``, ``model``, ``non_finite``, ``output_folder``,
        ``precession``, ``rejected_steps``, ``rhs_evaluations``, ``simulated_time_s``,
        ``step_limited_by``, ``steps``, ``wall_time_s``, ``whirl_ratio``.
    """
    model = as_model(model)
    options = dict(locals())
    for name in ("model", "tables", "progress"):
        options.pop(name)
    options["keep_tables"] = tables
    return call("simulate", options, Run, model=model, groups={"operating": OPERATING},
                progress=progress)


def wear(
    model: ModelLike = None,
    *,
    speed=None, outer_speed=None, radial_load=None, axial_load=None,
    load_direction: Optional[str] = None, oil_temperature=None, misalignment=None,
    life: Optional[Quantity] = None,
    period: Optional[Quantity] = None,
    method: Optional[str] = None,
    revolutions: Optional[int] = None,
    settle: Optional[int] = None,
    pressure: Optional[str] = None,
    exposure_width: Optional[str] = None,
    seed_literal_hardness: bool = False,
    max_clearance_increase: Optional[Quantity] = None,
    max_depth: Optional[Quantity] = None,
    window_settle: Optional[Quantity] = None,
    window: Optional[Quantity] = None,
    out: Optional[PathLike] = None,
    report: bool = False,
    progress: Progress = None,
) -> Result:
    """Archard wear of raceways, rollers, cage bars, roller ends and ribs over the bearing's
    life, fed back into the geometry each period (`rolldyn wear`).

    Parameters
    ----------
    model : Model, path or None
    speed, outer_speed, radial_load, axial_load, load_direction, oil_temperature, misalignment
        Overrides of the model's operating point.
    life : float or str, optional
        Life to reach, default 25 000 h (s as a number).
    period : float or str, optional
        Wear period, default 1905 h, or ``"auto"``.
    method : {"direct", "averaged"}, optional
    revolutions, settle : int, optional
        Cage revolutions recorded per period, and run and discarded before.
    pressure : {"slices", "boussinesq"}, optional
    exposure_width : {"full", "half"}, optional
    seed_literal_hardness : bool
    max_clearance_increase, max_depth : float or str, optional
        Stop criteria.
    window_settle, window : float or str, optional
        Dynamics windows of a tapered bearing.
    out : path, optional
        Output folder, default ``out/<model>-wear``.
    report : bool
        Write ``out/report.html`` at the end.
    progress : bool or callable, optional
        Per period; Ctrl-C stops after the running period, keeping what was written.

    Returns
    -------
    Result
        Table ``periods``; summary keys: ``model``, ``method``, ``requested_life_h``,
        ``revolutions``, ``settle_revolutions``, ``life_h``, ``stop``, ``periods``,
        ``max_depth_m``, ``roller_depth_from_bar_m``, ``clearance_increase_m``,
        ``initial_contacts``, ``convergence``, ``wall_time_s``, ``dynamics_wall_s``,
        ``wear_wall_s``, ``output_folder``, ``files``.
    """
    model = as_model(model)
    options = dict(locals())
    for name in ("model", "progress"):
        options.pop(name)
    return call("wear", options, Result, model=model, groups={"operating": OPERATING},
                progress=progress)


def fatigue(
    model: ModelLike = None,
    *,
    speed=None, outer_speed=None, radial_load=None, axial_load=None,
    load_direction: Optional[str] = None, oil_temperature=None, misalignment=None,
    stress: Optional[str] = None,
    revolutions: Optional[int] = None,
    inclusion: Optional[str] = None,
    mean_stress: Optional[str] = None,
    fillet_radius: Optional[Quantity] = None,
    mesh_size: Optional[Quantity] = None,
    fillet_mesh_size: Optional[Quantity] = None,
    stress_concentration: Optional[Sequence[float]] = None,
    sn_curve: Optional[PathLike] = None,
    coating_factor: Optional[float] = None,
    safety_factor: Optional[float] = None,
    below_knee: Optional[str] = None,
    loads: Optional[PathLike] = None,
    out: Optional[PathLike] = None,
    report: bool = False,
    cache: Optional[PathLike] = None,
    progress: Progress = None,
) -> Result:
    """Cage high-cycle fatigue from one steady revolution of the dynamics (`rolldyn fatigue`):
    frame or CalculiX stresses, rainflow, S–N, Miner, inclusion.

    Parameters
    ----------
    model : Model, path or None
    speed, outer_speed, radial_load, axial_load, load_direction, oil_temperature, misalignment
        Overrides of the model's operating point.
    stress : {"frame", "calculix"}, optional
    revolutions : int, optional
        Cage revolutions run before the recorded one.
    inclusion : {"debonded", "bonded"}, optional
    mean_stress : {"none", "goodman", "gerber", "swt"}, optional
    fillet_radius : float or str, optional
    mesh_size, fillet_mesh_size : float or str, optional
        Element sizes of the CalculiX solid model away from the fillets (default 8 mm) and at
        the fillet corners (default 0.6 mm); with ``stress="calculix"``.
    stress_concentration : pair of float, optional
    sn_curve : path, optional
        CSV rows ``N, sigma_a_MPa`` replacing the S–N curve of the cage's material.
    coating_factor : float, optional
        Replaces the coating factor of ``cage.plating`` (silver: 1.5); refused on an unplated
        cage.
    safety_factor : float, optional
    below_knee : {"no-damage", "extrapolate", "haibach"}, optional
    loads : path, optional
        A cage-load export (`simulate(cage_loads=...)`) instead of a dynamics run.
    out : path, optional
    report : bool
    cache : path, optional
        Cache folder of the CalculiX unit cases.
    progress : bool or callable, optional
        Per stage (dynamics, stresses, damage, files); Ctrl-C stops the dynamics run.

    Returns
    -------
    Result
        Summary keys: ``model``, ``stress_model``, ``load_sets``, ``cage_speed_rpm``,
        ``stress_concentration``, ``solid_mesh`` (CalculiX element sizes, m),
        ``damage_per_revolution``, ``life_revolutions``,
        ``life_hours``, ``extrapolated_life_revolutions``, ``critical_location``,
        ``critical_point_m``, ``max_stress_pa``, ``endurance_margin``,
        ``stress_safety_factor``, ``maxima``, ``sn`` (the S–N curve's material, source,
        ultimate strength and coating factor with its source), ``inclusion_life_revolutions``,
        ``inclusion_max_stress_pa``, ``inclusion_location``,
        ``inclusion_endurance_margin``, ``points``, ``dynamics_wall_s``,
        ``wall_time_s``, ``files``.
    """
    model = as_model(model) if loads is None else None
    options = dict(locals())
    for name in ("model", "progress"):
        options.pop(name)
    return call("fatigue", options, Result, model=model, groups={"operating": OPERATING},
                progress=progress)


def rainflow(history: PathLike, *, column: Optional[str] = None, periodic: bool = False) -> Result:
    """Rainflow count of a stress history (`rolldyn fatigue rainflow`).

    Parameters
    ----------
    history : path
        A CSV file: one value per row (the first column, or `column` of a file with a header).
    column : str, optional
        The column to count, by its header name.
    periodic : bool
        Count the history as one period of a repeated signal.

    Returns
    -------
    Result
        Table ``cycles`` (range, mean, count); summary keys: ``history``, ``periodic``,
        ``values``, ``cycles``.
    """
    return call("rainflow", dict(history=history, column=column, periodic=periodic), Result)


def startup(model: ModelLike, *, jobs: Optional[int] = None, revolutions: Optional[float] = None,
            average: Optional[float] = None, points: Optional[Sequence[str]] = None,
            out: Optional[PathLike] = None, progress: Progress = None) -> Result:
    """Engine start-up: the dynamics at the frozen time points of the model's schedules
    (`rolldyn startup`).

    Parameters
    ----------
    model : Model or path
        A model with speed and load schedules.
    jobs : int, optional
        Parallel jobs, default all cores.
    revolutions, average : float, optional
        Cage revolutions per point, and the last ones averaged.
    points : sequence of str, optional
        Run only these points, by label.
    out : path, optional
    progress : bool or callable, optional
        Per finished point; Ctrl-C starts no new points.

    Returns
    -------
    Result
        Tables ``startup`` and ``startup_revolutions``; summary keys: ``model``,
        ``revolutions``, ``average_revolutions``, ``output_folder``, ``points``.
    """
    model = as_model(model)
    options = dict(jobs=jobs, revolutions=revolutions, average=average,
                   points=None if points is None else list(points), out=out)
    return call("startup", options, Result, model=model, progress=progress)
