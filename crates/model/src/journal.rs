//! Journal-bearing model files (`rolldyn journal --file`, docs/reynolds.md): the TOML schema,
//! its checks with errors that name the file, line, key and reason, and the conversion into
//! `rolldyn_reynolds` types (SPEC §8.6, seed 002 ch. 4).

use crate::{Document, ModelError, read};
use rolldyn_reynolds::compliance::liner::{
    AnalyticLinerKernel, LinerKernel, Material, two_layer, winkler,
};
use rolldyn_reynolds::journal::{FilmStart, JournalBearing, JournalOperating};
use rolldyn_reynolds::thermal::ThermalModel;
use rolldyn_reynolds::{Barus, Cavitation, Isoviscous, Petrusevich, Viscosity};
use rolldyn_units::{
    AngularSpeed, DynamicViscosity, Force, Length, PerPressure, Pressure, Quantity, Temperature,
    ThermalConductivity,
};
use serde::Deserialize;
use std::path::Path;

/// Fourier harmonics of the thermal model when the file gives none (seed 002 §4.5: n = 10).
const DEFAULT_HARMONICS: usize = 10;
/// Most Fourier harmonics of the thermal model (the seed's 10 resolve the temperature field).
const MAX_HARMONICS: usize = 200;

// Plausibility bounds of a journal file (docs/reynolds.md, "Plausibility bounds"): values a
// journal bearing does not have are refused at their key, not left to fail in the solver.

/// Journal radius R, m.
const RADIUS_M: (f64, f64) = (1e-4, 2.5);
const RADIUS_WHY: &str =
    "fluid-dynamic spindle bearings are ≈ 2 mm in bore, the largest turbine bearings ≈ 4 m";
/// Length over diameter L/(2R).
const LENGTH_PER_DIAMETER: (f64, f64) = (0.01, 10.0);
const LENGTH_WHY: &str = "0.01…10 journal diameters (usual L/D is 0.2…2)";
/// Radial clearance over radius c/R.
const CLEARANCE_PER_RADIUS: (f64, f64) = (1e-5, 0.1);
const CLEARANCE_WHY: &str = "1e-5…0.1 of the radius (usual c/R ≈ 1e-3)";
/// Largest journal surface speed ωR, m/s.
const MAX_SURFACE_SPEED_M_S: f64 = 300.0;
const SPEED_WHY: &str = "nonzero (a journal bearing carries its load by rotation) and a \
                         surface speed of at most 300 m/s (turbine bearings run at ≈ 150 m/s)";
/// Largest specific load W/(2RL), Pa.
const MAX_SPECIFIC_LOAD_PA: f64 = 100e6;
const LOAD_WHY: &str =
    "a specific load W/(2RL) of at most 100 MPa (white metal carries ≈ 20 MPa, bronze ≈ 50 MPa)";
/// Dynamic viscosity μ₀, Pa s.
const VISCOSITY_PA_S: (f64, f64) = (1e-6, 1e3);
const VISCOSITY_WHY: &str = "gases ≈ 2e-5 Pa s … cold gear oils ≈ 10 Pa s";
/// Largest pressure–viscosity coefficient α, 1/Pa.
const MAX_PRESSURE_VISCOSITY_PER_PA: f64 = 1e-7;
/// Largest viscosity–temperature slope Ω₀, 1/K.
const MAX_VISCOSITY_TEMPERATURE_PER_K: f64 = 1.0;
/// Young's modulus of a liner or housing, Pa.
const MODULUS_PA: (f64, f64) = (1e5, 1.2e12);
const MODULUS_WHY: &str = "soft elastomer liners … diamond";
/// Largest outer radius of a housing or of the thermal model, m.
const MAX_OUTER_RADIUS_M: f64 = 5.0;
/// Thermal conductivity, W/(m K).
const CONDUCTIVITY_W_M_K: (f64, f64) = (1e-2, 500.0);
const CONDUCTIVITY_WHY: &str = "insulating polymers ≈ 0.1 … copper ≈ 400 W/(m K)";

/// What the journal solve is given.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum JournalTarget {
    /// Eccentricity ratio ε = e/c, 0 < ε < 1.
    Eccentricity(f64),
    /// Static load W, N: the solve finds ε and the attitude.
    Load(f64),
}

/// A rejected [`journal_target`]: the key at fault and why.
#[derive(Debug, Clone, PartialEq)]
pub struct TargetError {
    pub key: String,
    pub reason: String,
}

/// The target from an optional eccentricity and an optional load (exactly one must be given);
/// `prefix` spells the keys in messages (`operating.`, `--`).
pub fn journal_target(
    eccentricity: Option<f64>,
    load: Option<f64>,
    prefix: &str,
) -> Result<JournalTarget, TargetError> {
    let error = |key: &str, reason: String| TargetError {
        key: if key.is_empty() {
            prefix.trim_matches(['.', '-']).to_string()
        } else {
            format!("{prefix}{key}")
        },
        reason,
    };
    match (eccentricity, load) {
        (Some(e), None) if e.is_finite() && e > 0.0 && e < 1.0 => {
            Ok(JournalTarget::Eccentricity(e))
        }
        (Some(e), None) => Err(error(
            "eccentricity",
            format!(
                "{e}: must satisfy 0 < ε < 1 (ε ≥ 1 is metal contact; at ε = 0 the load and \
                 Sommerfeld number are undefined)"
            ),
        )),
        (None, Some(w)) if w.is_finite() && w > 0.0 => Ok(JournalTarget::Load(w)),
        (None, Some(w)) => Err(error("load", format!("{w} N: must be > 0"))),
        (Some(_), Some(_)) => Err(error(
            "",
            format!("give either {prefix}eccentricity or {prefix}load, not both"),
        )),
        (None, None) => Err(error(
            "",
            format!("give {prefix}eccentricity or {prefix}load"),
        )),
    }
}

/// Grid `NxM` (circumferential × axial nodes over the full length), N ∈ 8…4000, M ∈ 3…2000.
pub fn parse_grid(text: &str) -> Result<(usize, usize), String> {
    let bad = || {
        format!(
            "'{text}': expected NxM (circumferential × axial nodes), e.g. 120x40, with N ≥ 8 and M ≥ 3"
        )
    };
    let (a, b) = text.split_once(['x', 'X', '×']).ok_or_else(bad)?;
    let n: usize = a.trim().parse().map_err(|_| bad())?;
    let m: usize = b.trim().parse().map_err(|_| bad())?;
    if n < 8 || m < 3 || n > 4000 || m > 2000 {
        return Err(bad());
    }
    Ok((n, m))
}

/// Solver choices of a model file; `None` where the file is silent.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct JournalSolver {
    pub cavitation: Option<Cavitation>,
    pub grid: Option<(usize, usize)>,
    pub film_start: Option<FilmStart>,
}

/// Everything a journal model file describes, in SI units.
pub struct JournalModel {
    pub bearing: JournalBearing,
    pub viscosity: Box<dyn Viscosity>,
    /// `isoviscous`, `barus` or `petrusevich`.
    pub viscosity_law: &'static str,
    pub operating: JournalOperating,
    pub target: JournalTarget,
    pub solver: JournalSolver,
}

/// Reads and checks a journal model file; `temperature_k` is the operating temperature when
/// the file gives none.
pub fn load_journal(path: &Path, temperature_k: f64) -> Result<JournalModel, ModelError> {
    let (text, file) = read(path)?;
    parse_journal(&text, &file, temperature_k)
}

/// Parses and checks journal model text; `file` names it in errors.
pub fn parse_journal(
    text: &str,
    file: &str,
    temperature_k: f64,
) -> Result<JournalModel, ModelError> {
    let document = Document::<JournalFile>::parse(text, file)?;
    let m = &document.schema;
    let within = |key: &str, v: f64, (lo, hi): (f64, f64), unit: &str, why: &str| {
        if (lo..=hi).contains(&v) {
            Ok(v)
        } else {
            Err(document.error(
                key,
                format!("{v:e} {unit} is implausible (expected {lo:e}…{hi:e} {unit}: {why})"),
            ))
        }
    };
    let temperature = |key: &str, kelvin: f64| {
        crate::bounds::check_temperature(key, kelvin)
            .map(|()| kelvin)
            .map_err(|e| document.error(key, e.reason))
    };
    let g = &m.geometry;
    let r = within("geometry.radius", g.radius.si(), RADIUS_M, "m", RADIUS_WHY)?;
    let length = within(
        "geometry.length",
        g.length.si(),
        (
            LENGTH_PER_DIAMETER.0 * 2.0 * r,
            LENGTH_PER_DIAMETER.1 * 2.0 * r,
        ),
        "m",
        LENGTH_WHY,
    )?;
    let c = within(
        "geometry.clearance",
        g.clearance.si(),
        (CLEARANCE_PER_RADIUS.0 * r, CLEARANCE_PER_RADIUS.1 * r),
        "m",
        CLEARANCE_WHY,
    )?;
    let mut bearing = JournalBearing::new(r, length, c);
    let speed = m.operating.speed.si();
    within(
        "operating.speed",
        speed.abs(),
        (f64::MIN_POSITIVE, MAX_SURFACE_SPEED_M_S / r),
        "rad/s",
        SPEED_WHY,
    )?;
    if let Some(load) = m.operating.load.map(Quantity::si) {
        within(
            "operating.load",
            load,
            (f64::MIN_POSITIVE, MAX_SPECIFIC_LOAD_PA * 2.0 * r * length),
            "N",
            LOAD_WHY,
        )?;
    }
    let t_op = match m.operating.temperature {
        Some(t) => temperature("operating.temperature", t.si())?,
        None => temperature_k,
    };
    if let Some(t) = m.viscosity.t_ref {
        temperature("viscosity.t_ref", t.si())?;
    }
    let (viscosity, viscosity_law) = m
        .viscosity
        .law(t_op)
        .map_err(|(k, why)| document.error(&format!("viscosity.{k}"), why))?;
    if let Some(liner) = &m.liner {
        bearing.liner = Some(
            liner
                .kernel(r + c)
                .map_err(|(k, why)| document.error(&format!("liner.{k}"), why))?,
        );
    }
    if let Some(th) = &m.thermal {
        let outer_radius = th.outer_radius.si();
        if !(outer_radius > r + c && outer_radius <= MAX_OUTER_RADIUS_M) {
            return Err(document.error(
                "thermal.outer_radius",
                format!(
                    "{outer_radius:e} m: must exceed the bore radius {:e} m and be at most {MAX_OUTER_RADIUS_M} m",
                    r + c
                ),
            ));
        }
        let harmonics = th.harmonics.unwrap_or(DEFAULT_HARMONICS);
        if !(1..=MAX_HARMONICS).contains(&harmonics) {
            return Err(document.error(
                "thermal.harmonics",
                format!("{harmonics}: must be 1…{MAX_HARMONICS} (seed 002 §4.5 uses 10)"),
            ));
        }
        bearing.thermal = Some(ThermalModel {
            conductivity: within(
                "thermal.conductivity",
                th.conductivity.si(),
                CONDUCTIVITY_W_M_K,
                "W/(m K)",
                CONDUCTIVITY_WHY,
            )?,
            ambient_temperature: temperature(
                "thermal.ambient_temperature",
                th.ambient_temperature.si(),
            )?,
            outer_radius,
            harmonics,
        });
    }
    let target = journal_target(
        m.operating.eccentricity,
        m.operating.load.map(Quantity::si),
        "operating.",
    )
    .map_err(|e| document.error(&e.key, e.reason))?;
    let s = m.solver.as_ref();
    let grid = match s.and_then(|s| s.grid.as_deref()) {
        Some(text) => Some(parse_grid(text).map_err(|why| document.error("solver.grid", why))?),
        None => None,
    };
    Ok(JournalModel {
        bearing,
        viscosity,
        viscosity_law,
        operating: JournalOperating {
            journal_speed: m.operating.speed.si(),
            bearing_speed: 0.0,
            temperature: t_op,
        },
        target,
        solver: JournalSolver {
            cavitation: s.and_then(|s| s.cavitation).map(CavitationName::model),
            grid,
            film_start: s.and_then(|s| s.film_start).map(FilmStartName::model),
        },
    })
}

// ---------------------------------------------------------------- schema

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct JournalFile {
    geometry: GeometryFile,
    operating: OperatingFile,
    viscosity: ViscosityFile,
    liner: Option<LinerFile>,
    thermal: Option<ThermalFile>,
    solver: Option<SolverFile>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct GeometryFile {
    /// Journal radius R (bush bore R₁ = R + c).
    radius: Quantity<Length>,
    length: Quantity<Length>,
    clearance: Quantity<Length>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct OperatingFile {
    speed: Quantity<AngularSpeed>,
    eccentricity: Option<f64>,
    load: Option<Quantity<Force>>,
    temperature: Option<Quantity<Temperature>>,
}

#[derive(Deserialize, Clone, Copy)]
#[serde(rename_all = "kebab-case")]
enum LawName {
    Isoviscous,
    Barus,
    Petrusevich,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ViscosityFile {
    law: LawName,
    mu0: Quantity<DynamicViscosity>,
    alpha: Option<Quantity<PerPressure>>,
    /// Viscosity–temperature slope Ω₀, 1/K (plain number).
    omega0_per_k: Option<f64>,
    /// Reference temperature of μ₀ (default: the operating temperature).
    t_ref: Option<Quantity<Temperature>>,
}

/// A key of a table (relative to the table) and why its value is rejected.
type KeyError = (&'static str, String);

impl ViscosityFile {
    /// The viscosity law and its name; μ₀ at `t_op` unless `t_ref` is given.
    fn law(&self, t_op: f64) -> Result<(Box<dyn Viscosity>, &'static str), KeyError> {
        let mu0 = self.mu0.si();
        let (lo, hi) = VISCOSITY_PA_S;
        if !(lo..=hi).contains(&mu0) {
            return Err((
                "mu0",
                format!(
                    "{mu0:e} Pa s is implausible (expected {lo:e}…{hi:e} Pa s: {VISCOSITY_WHY})"
                ),
            ));
        }
        let alpha = self.alpha.map_or(0.0, Quantity::si);
        if !(0.0..=MAX_PRESSURE_VISCOSITY_PER_PA).contains(&alpha) {
            return Err((
                "alpha",
                format!(
                    "{alpha:e} 1/Pa: must be 0…{MAX_PRESSURE_VISCOSITY_PER_PA:e} 1/Pa (mineral oils ≈ 2e-8 1/Pa)"
                ),
            ));
        }
        Ok(match self.law {
            LawName::Isoviscous => (Box::new(Isoviscous { mu: mu0 }), "isoviscous"),
            LawName::Barus => (Box::new(Barus { mu0, alpha }), "barus"),
            LawName::Petrusevich => {
                let omega0 = self
                    .omega0_per_k
                    .ok_or(("omega0_per_k", "required by the Petrusevich law".into()))?;
                if !(0.0..=MAX_VISCOSITY_TEMPERATURE_PER_K).contains(&omega0) {
                    return Err((
                        "omega0_per_k",
                        format!(
                            "{omega0:e} 1/K: must be 0…{MAX_VISCOSITY_TEMPERATURE_PER_K} 1/K (oils ≈ 0.02–0.05 1/K)"
                        ),
                    ));
                }
                let law = Petrusevich {
                    mu0,
                    alpha,
                    omega0,
                    t_ref_k: self.t_ref.map_or(t_op, Quantity::si),
                };
                (Box::new(law), "petrusevich")
            }
        })
    }
}

#[derive(Deserialize, Clone, Copy)]
#[serde(rename_all = "kebab-case")]
enum KernelName {
    Analytic,
    Winkler,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct LinerFile {
    thickness: Quantity<Length>,
    modulus: Quantity<Pressure>,
    poisson: f64,
    kernel: Option<KernelName>,
    housing: Option<HousingFile>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct HousingFile {
    outer_radius: Quantity<Length>,
    modulus: Quantity<Pressure>,
    poisson: f64,
}

/// An elastic material (E > 0, −1 < ν < 0.5) or the key at fault.
fn material(
    modulus: f64,
    poisson: f64,
    keys: (&'static str, &'static str),
) -> Result<Material, KeyError> {
    let (lo, hi) = MODULUS_PA;
    if !(lo..=hi).contains(&modulus) {
        return Err((
            keys.0,
            format!("{modulus:e} Pa is implausible (expected {lo:e}…{hi:e} Pa: {MODULUS_WHY})"),
        ));
    }
    if !(poisson > -1.0 && poisson < 0.5) {
        return Err((keys.1, "must lie in (−1, 0.5)".into()));
    }
    Ok(Material {
        e: modulus,
        nu: poisson,
    })
}

impl LinerFile {
    /// The liner kernel on bore radius `r1`: stiffness k₀ of the liner in its housing (seed 002
    /// (4.33)) or, without a housing, a Winkler layer on a rigid one.
    fn kernel(&self, r1: f64) -> Result<LinerKernel, KeyError> {
        let t = self.thickness.si();
        if !(t > 0.0 && t <= r1) {
            return Err((
                "thickness",
                format!("{t:e} m: must be > 0 and at most the bore radius {r1:e} m"),
            ));
        }
        let liner = material(self.modulus.si(), self.poisson, ("modulus", "poisson"))?;
        let k0 = match &self.housing {
            Some(h) => {
                let r3 = h.outer_radius.si();
                if !(r3 > r1 + t && r3 <= MAX_OUTER_RADIUS_M) {
                    return Err((
                        "housing.outer_radius",
                        format!(
                            "{r3:e} m: must exceed the liner outer radius {:.6} m and be at most {MAX_OUTER_RADIUS_M} m",
                            r1 + t
                        ),
                    ));
                }
                let housing = material(
                    h.modulus.si(),
                    h.poisson,
                    ("housing.modulus", "housing.poisson"),
                )?;
                two_layer(r1, r1 + t, r3, liner, housing)
            }
            None => winkler(t, liner.e, liner.nu),
        };
        Ok(match self.kernel.unwrap_or(KernelName::Analytic) {
            KernelName::Analytic => LinerKernel::Analytic(AnalyticLinerKernel::seed(k0)),
            KernelName::Winkler => LinerKernel::Winkler { k0 },
        })
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ThermalFile {
    conductivity: Quantity<ThermalConductivity>,
    ambient_temperature: Quantity<Temperature>,
    outer_radius: Quantity<Length>,
    harmonics: Option<usize>,
}

#[derive(Deserialize, Clone, Copy)]
#[serde(rename_all = "kebab-case")]
enum CavitationName {
    Reynolds,
    Jfo,
    None,
}

impl CavitationName {
    fn model(self) -> Cavitation {
        match self {
            Self::Reynolds => Cavitation::Reynolds,
            Self::Jfo => Cavitation::Jfo,
            Self::None => Cavitation::None,
        }
    }
}

#[derive(Deserialize, Clone, Copy)]
#[serde(rename_all = "kebab-case")]
enum FilmStartName {
    MaxGap,
    Free,
}

impl FilmStartName {
    fn model(self) -> FilmStart {
        match self {
            Self::MaxGap => FilmStart::MaxGap,
            Self::Free => FilmStart::Free,
        }
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SolverFile {
    cavitation: Option<CavitationName>,
    grid: Option<String>,
    film_start: Option<FilmStartName>,
}

#[cfg(test)]
mod tests {
    use super::*;

    const SEED: &str = include_str!("../../../examples/journal/seed002-ch4.toml");

    fn error(text: &str) -> ModelError {
        match parse_journal(text, "bad.toml", 300.0) {
            Err(e) => e,
            Ok(_) => panic!("accepted: {text}"),
        }
    }

    #[test]
    fn the_seed_example_converts() {
        let m = parse_journal(SEED, "seed.toml", 300.0).unwrap();
        assert_eq!(m.viscosity_law, "petrusevich");
        assert_eq!(m.target, JournalTarget::Eccentricity(0.95));
        assert!(m.bearing.liner.is_some() && m.bearing.thermal.is_some());
        assert_eq!(m.solver.grid, Some((120, 40)));
        assert_eq!(m.solver.film_start, Some(FilmStart::Free));
        assert!((m.operating.temperature - 313.15).abs() < 1e-9);
    }

    #[test]
    fn errors_name_line_key_and_reason() {
        let text = SEED.replace("poisson = 0.34", "poisson = 0.7");
        let e = error(&text);
        assert_eq!(e.key, "liner.poisson");
        let line = text.lines().position(|l| l.contains("0.7")).unwrap() + 1;
        assert_eq!(e.position.map(|p| p.0), Some(line), "{e}");
        let text = SEED.replace("poisson = 0.34", "poisson = 0.34\nyoung = 1");
        let e = error(&text);
        assert!(e.to_string().contains("liner.young"), "{e}");
        let text = SEED.replace("grid = \"120x40\"", "grid = \"2x2\"");
        let e = error(&text);
        assert_eq!(e.key, "solver.grid");
        let text = SEED.replace("eccentricity = 0.95", "eccentricity = 1.5");
        let e = error(&text);
        assert_eq!(e.key, "operating.eccentricity");
        assert!(e.reason.contains('ε'));
    }

    #[test]
    fn targets_need_exactly_one_valid_value() {
        assert_eq!(
            journal_target(None, Some(5.0), "--"),
            Ok(JournalTarget::Load(5.0))
        );
        assert_eq!(
            journal_target(Some(1.0), None, "--").unwrap_err().key,
            "--eccentricity"
        );
        assert!(journal_target(None, None, "--").is_err());
        assert!(journal_target(Some(0.5), Some(5.0), "--").is_err());
        assert_eq!(parse_grid("60×20"), Ok((60, 20)));
        assert!(parse_grid("7x20").is_err());
    }
}
