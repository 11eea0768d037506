//! Traction / friction of lubricated contacts — **one entry point [`traction()`]** used by the
//! dynamics (per slice, per integrator stage), the quasi-static model and the scuffing check.
//!
//! Laws ([`FrictionLaw`]):
//! * [`FrictionLaw::Lubricated`] (seed 000): μ_hd from Muraki (1.4)–(1.9) ([`mod@muraki`]) or a constant,
//!   μ_bd from Kragelsky (2.10) ([`boundary`]) or a constant, blended by Λ (1.3) ([`mixed`]);
//! * [`FrictionLaw::Seed001`]: asperity fraction + film shear + Blok flash temperature ([`flash`]);
//! * [`FrictionLaw::TwoLevel`]: the regularised two-level law of SPEC §3.4 ([`two_level`]).
//!
//! Sign convention of [`Traction::coefficient`]: it has the sign of the sliding speed
//! v = v₁ − v₂ (an odd function of v); the friction force on surface 1 is −coefficient·Q along the
//! sliding axis, on surface 2 +coefficient·Q. (The raw [`TwoLevelLaw::coefficient`] keeps the SPEC's
//! opposite sign, μ(v) = −sign(v)μ_d.)
//!
//! Guarantees (tested): μ is odd in v; μ → 0 as v → 0 (for every law except a constant boundary /
//! hydrodynamic coefficient without regularisation); finite at zero rolling speed (u is floored at
//! [`TractionConfig::min_rolling_speed_m_s`] in s = v/u and in the Muraki groups, the film → 0);
//! continuous across the regime switches of (1.3) and across the elastic/viscous branches of (1.8).

pub mod batch;
pub mod boundary;
pub mod flash;
pub mod mixed;
pub mod muraki;
pub mod table;
pub mod two_level;

pub use batch::{BatchContact, SliceBatch, SliceColumnsMut};
pub use boundary::{BoundaryFriction, kragelsky};
pub use flash::{Seed001Inputs, Seed001Result, Seed001Settings, seed001_friction};
pub use mixed::{MixedLimits, mixed_friction, mixed_friction_weighted};
use muraki::{MurakiContact, MurakiSlice, muraki_slice};
pub use muraki::{MurakiInputs, MurakiOutput, MurakiSettings, Rheology, SmallShearRate, muraki};
pub use two_level::{TwoLevelLaw, regularisation};

use crate::contact_state::ContactState;
use crate::error::LubError;
use crate::film::{FilmFormula, FilmInputs, FilmSettings, film_core, resolve_formula};
use crate::lubricant::{Lubricant, Property};
use crate::regime::{FrictionRegime, LambdaDefinition};
use table::{HotProps, PropertyTable};

/// Hydrodynamic (full-film) friction law.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Hydrodynamic {
    /// Muraki thermal visco-elastic model (SPEC §4.5).
    Muraki(MurakiSettings),
    /// constant μ_hd (e.g. 0.00075…0.02 for cage contacts, seed 000 §3.3)
    Constant(f64),
}

/// The seed 000 lubricated friction law: μ_hd, μ_bd and the Λ blend (1.3).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LubricatedFriction {
    /// hydrodynamic part
    pub hydrodynamic: Hydrodynamic,
    /// boundary part
    pub boundary: BoundaryFriction,
    /// Λ limits of (1.3); `None` → pure hydrodynamic friction (no blend)
    pub mixed: Option<MixedLimits>,
}

/// Friction law of a contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum FrictionLaw {
    /// seed 000 EHL traction with mixed/boundary blend.
    Lubricated(LubricatedFriction),
    /// seed 001 asperity + film-shear + flash-temperature model.
    Seed001(Seed001Settings),
    /// SPEC §3.4 two-level law with constant μ_s, μ_d (roller-end / cage contacts).
    TwoLevel(TwoLevelLaw),
}

/// Full configuration of a traction model.
#[derive(Debug, Clone, PartialEq)]
pub struct TractionConfig {
    /// the oil (not needed for [`FrictionLaw::TwoLevel`])
    pub oil: Option<Lubricant>,
    /// friction law
    pub law: FrictionLaw,
    /// film formula and starvation
    pub film: FilmSettings,
    /// Λ definition; `None` → (1.2) for `Lubricated`, Tallian for `Seed001` (F-44)
    pub lambda_definition: Option<LambdaDefinition>,
    /// STEP regularisation half-width around v = 0, m/s (0 = off; SPEC §3.4 with μ_s = μ_d)
    pub regularisation_speed_m_s: f64,
    /// floor of |u| in s = v/u and in the Muraki groups, m/s (default 1e-3)
    pub min_rolling_speed_m_s: f64,
    /// clamp the property temperature to the oil's valid range (default true; flagged)
    pub clamp_temperature: bool,
}

/// A validated traction model (construct with [`TractionModel::new`] or the shortcuts).
#[derive(Debug, Clone, PartialEq)]
pub struct TractionModel {
    cfg: TractionConfig,
    lambda_def: LambdaDefinition,
    table: Option<PropertyTable>,
}

/// Bit set of warnings raised by one evaluation (SPEC §9.2 "emit a warning with the flag id").
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Warnings(pub u16);

impl Warnings {
    /// the oil temperature was outside the oil's range and was clamped
    pub const TEMPERATURE_CLAMPED: u16 = 1;
    /// F-34: negative square-root argument in (1.8) (literal mode)
    pub const SQRT_NEGATIVE_F34: u16 = 2;
    /// F-34: σ < 0.5 with ln 2σ (literal mode)
    pub const SIGMA_INVALID_F34: u16 = 4;
    /// film formula did not fit the geometry; `Auto` used instead
    pub const FILM_FORMULA_MISMATCH: u16 = 8;
    /// (2.20) not satisfied for (2.19) (F-30)
    pub const PVE_CONDITION_FAILED: u16 = 16;
    /// seed 001 flash iteration did not converge
    pub const FLASH_NOT_CONVERGED: u16 = 32;
    /// |u| below the floor: s and the Muraki groups use the floor
    pub const ROLLING_SPEED_FLOORED: u16 = 64;
    /// Q ≤ 0: zero traction returned
    pub const UNLOADED: u16 = 128;

    /// Is the given flag set?
    pub fn contains(self, flag: u16) -> bool {
        self.0 & flag != 0
    }
    /// No warning?
    pub fn is_empty(self) -> bool {
        self.0 == 0
    }
    /// Names of the set flags.
    pub fn names(self) -> Vec<&'static str> {
        const N: [(u16, &str); 8] = [
            (1, "temperature clamped to the oil's range"),
            (2, "F-34 negative square-root argument in (1.8)"),
            (4, "F-34 sigma < 0.5 with ln(2 sigma)"),
            (8, "film formula does not fit the geometry (auto used)"),
            (16, "(2.20) piezoviscous-elastic condition not met (F-30)"),
            (32, "seed 001 flash-temperature iteration not converged"),
            (64, "rolling speed below the floor"),
            (128, "unloaded contact"),
        ];
        N.iter()
            .filter(|(b, _)| self.0 & b != 0)
            .map(|(_, n)| *n)
            .collect()
    }
}

/// Result of [`traction()`].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Traction {
    /// friction/traction coefficient μ, sign of the sliding speed (see module docs)
    pub coefficient: f64,
    /// hydrodynamic part μ_hd ≥ 0 (for `Seed001`: f; for `TwoLevel`: |μ|) — the friction-curve value
    /// used by the scuffing criterion
    pub hydrodynamic: f64,
    /// boundary part μ_bd ≥ 0 (NaN when not used: no mixed law, or Λ ≥ Λ_hd)
    pub boundary: f64,
    /// regime by (1.3) (`Seed001`: Mixed if the asperity fraction > 10⁻³; `TwoLevel`: Boundary)
    pub regime: FrictionRegime,
    /// frictional heat power N = |μ| Q |v| (2.21), W
    pub heat_power_w: f64,
    /// central film used for the shear, m (NaN for `TwoLevel`)
    pub film_central_m: f64,
    /// minimum film used for Λ, m
    pub film_minimum_m: f64,
    /// film parameter Λ
    pub lambda: f64,
    /// relative slip s = v/u (signed, u floored)
    pub slip: f64,
    /// mean contact pressure p̄, Pa
    pub mean_pressure_pa: f64,
    /// maximum contact pressure, Pa
    pub max_pressure_pa: f64,
    /// half-width b, m
    pub half_width_m: f64,
    /// contact oil temperature after the flash iteration (seed 001) or the input temperature, K
    pub contact_temperature_k: f64,
    /// film formula used (`None` when the caller imposed the film or for `TwoLevel`)
    pub film_formula: Option<FilmFormula>,
    /// warnings
    pub warnings: Warnings,
}

impl Traction {
    /// The result for an unloaded contact (Q ≤ 0): no friction, no film, Λ = ∞.
    fn unloaded(slip: f64, temperature_k: f64, warnings: u16) -> Self {
        Traction {
            lambda: f64::INFINITY,
            slip,
            film_central_m: f64::NAN,
            film_minimum_m: f64::NAN,
            contact_temperature_k: temperature_k,
            warnings: Warnings(warnings | Warnings::UNLOADED),
            ..Default::default()
        }
    }
}

/// `x > 0` and not NaN.
fn positive(x: f64) -> bool {
    x > 0.0
}

impl TractionModel {
    /// Validate a configuration: every property the law and film formula need must exist.
    pub fn new(cfg: TractionConfig) -> Result<TractionModel, LubError> {
        use Property::*;
        let mut needs: Vec<Property> = Vec::new();
        match &cfg.law {
            FrictionLaw::Lubricated(lf) => {
                needs.extend([Viscosity, Alpha]);
                if let Hydrodynamic::Muraki(m) = &lf.hydrodynamic {
                    needs.push(Gamma);
                    match m.rheology {
                        Rheology::LinearElastic { cap } => {
                            if !positive(cap) {
                                return Err(LubError::InvalidInput(
                                    "linear-elastic cap must be > 0".into(),
                                ));
                            }
                        }
                        Rheology::Isothermal => needs.push(Tau0),
                        Rheology::ViscoElastic => {
                            needs.extend([Tau0, Beta0, Kappa, Kf]);
                        }
                    }
                    if let SmallShearRate::SpecLinearBranch { sigma_min } = m.small_shear_rate
                        && !positive(sigma_min)
                    {
                        return Err(LubError::InvalidInput("sigma_min must be > 0".into()));
                    }
                }
                if let Some(l) = lf.mixed
                    && !(l.lambda_bd < l.lambda_hd && l.lambda_bd >= 0.0)
                {
                    return Err(LubError::InvalidInput(
                        "mixed friction needs 0 <= lambda_bd < lambda_hd".into(),
                    ));
                }
            }
            FrictionLaw::Seed001(_) => needs.extend([Viscosity, Alpha, Beta0, Kf]),
            FrictionLaw::TwoLevel(t) => {
                if !(t.v_s > 0.0 && t.v_d > t.v_s) {
                    return Err(LubError::InvalidInput(
                        "two-level law needs 0 < v_s < v_d".into(),
                    ));
                }
            }
        }
        if cfg.film.formula == FilmFormula::Seed001 {
            needs.extend([Beta0, Kf]);
        }
        if !needs.is_empty() {
            let oil = cfg.oil.as_ref().ok_or_else(|| {
                LubError::InvalidInput("this friction law needs a lubricant".into())
            })?;
            oil.require(&needs)?;
        }
        if !positive(cfg.min_rolling_speed_m_s) {
            return Err(LubError::InvalidInput(
                "min_rolling_speed_m_s must be > 0".into(),
            ));
        }
        if !positive(cfg.film.starvation_factor) {
            return Err(LubError::InvalidInput(
                "starvation_factor must be > 0".into(),
            ));
        }
        let lambda_def = cfg.lambda_definition.unwrap_or(match cfg.law {
            FrictionLaw::Seed001(_) => LambdaDefinition::Tallian,
            _ => LambdaDefinition::Seed000,
        });
        let table = cfg.oil.as_ref().map(PropertyTable::new);
        Ok(TractionModel {
            cfg,
            lambda_def,
            table,
        })
    }

    /// Default lubricated model for `oil`: Muraki visco-elastic, Kragelsky boundary, Λ blend with
    /// the oil's Λ_bd/Λ_hd if it has them (else pure hydrodynamic), film `Auto`, no regularisation.
    pub fn muraki(oil: Lubricant) -> Result<TractionModel, LubError> {
        Self::lubricated(oil, MurakiSettings::default())
    }

    /// As [`TractionModel::muraki`] with explicit Muraki settings.
    pub fn lubricated(oil: Lubricant, m: MurakiSettings) -> Result<TractionModel, LubError> {
        let mixed = oil.mixed_friction.map(|d| MixedLimits {
            lambda_bd: d.lambda_bd,
            lambda_hd: d.lambda_hd,
        });
        Self::new(TractionConfig {
            oil: Some(oil),
            law: FrictionLaw::Lubricated(LubricatedFriction {
                hydrodynamic: Hydrodynamic::Muraki(m),
                boundary: BoundaryFriction::Kragelsky,
                mixed,
            }),
            ..TractionConfig::default()
        })
    }

    /// The configuration.
    pub fn config(&self) -> &TractionConfig {
        &self.cfg
    }

    /// Oil properties used by the hot path at `t_k`: tabulated inside the oil's range (see
    /// [`table`]), closed form outside. Missing properties are NaN.
    #[inline]
    pub fn hot_properties(&self, t_k: f64) -> Option<HotProps> {
        let oil = self.cfg.oil.as_ref()?;
        Some(
            self.table
                .as_ref()
                .and_then(|tb| tb.get(t_k))
                .unwrap_or_else(|| HotProps::closed_form(oil, t_k)),
        )
    }

    /// Λ definition in use.
    pub fn lambda_definition(&self) -> LambdaDefinition {
        self.lambda_def
    }
}

impl TractionConfig {
    /// Sign of the traction for the sliding speed `v`: regularised over
    /// `regularisation_speed_m_s` when set, else the plain sign (0 at rest).
    #[inline(always)]
    fn sliding_sign(&self, v: f64) -> f64 {
        if self.regularisation_speed_m_s > 0.0 {
            regularisation(v, self.regularisation_speed_m_s)
        } else if v == 0.0 {
            0.0
        } else {
            v.signum()
        }
    }
}

impl Default for TractionConfig {
    fn default() -> Self {
        TractionConfig {
            oil: None,
            law: FrictionLaw::Lubricated(LubricatedFriction {
                hydrodynamic: Hydrodynamic::Muraki(MurakiSettings::default()),
                boundary: BoundaryFriction::Kragelsky,
                mixed: None,
            }),
            film: FilmSettings::default(),
            lambda_definition: None,
            regularisation_speed_m_s: 0.0,
            min_rolling_speed_m_s: 1e-3,
            clamp_temperature: true,
        }
    }
}

/// Traction of one contact state (see the module docs for conventions). Never fails and never
/// returns NaN for a validated model and finite inputs.
#[inline]
pub fn traction(state: &ContactState, model: &TractionModel) -> Traction {
    traction_with_film(state, model, state.film_thickness_m.map(|h| (h, h)))
}

/// [`traction`] with the central and minimum film `(h_c, h_min)` given by the caller (m): the
/// hydrodynamic friction uses `h_c`, Λ uses `h_min`. `None` computes both with the model's film
/// formula ([`TractionModel::prepare_contact`] shares one film among many slices).
#[inline]
fn traction_with_film(
    state: &ContactState,
    model: &TractionModel,
    film: Option<(f64, f64)>,
) -> Traction {
    let cfg = &model.cfg;
    let q = state.normal_force_n;
    let v = state.sliding_speed_m_s;
    let u_abs = state.rolling_speed_m_s.abs();
    let u_min = cfg.min_rolling_speed_m_s;
    let mut w = 0u16;
    if u_abs < u_min {
        w |= Warnings::ROLLING_SPEED_FLOORED;
    }
    let u_eff = u_abs.max(u_min);
    let s = v / u_eff;

    if let FrictionLaw::TwoLevel(law) = &cfg.law {
        let mu = -law.coefficient(v);
        return Traction {
            coefficient: mu,
            hydrodynamic: mu.abs(),
            boundary: f64::NAN,
            regime: FrictionRegime::Boundary,
            heat_power_w: mu.abs() * q.max(0.0) * v.abs(),
            film_central_m: f64::NAN,
            film_minimum_m: f64::NAN,
            lambda: f64::NAN,
            slip: s,
            mean_pressure_pa: f64::NAN,
            max_pressure_pa: f64::NAN,
            half_width_m: f64::NAN,
            contact_temperature_k: state.temperature_k,
            film_formula: None,
            warnings: Warnings(w),
        };
    }

    if q <= 0.0 {
        return Traction::unloaded(s, state.temperature_k, w);
    }
    if let FrictionLaw::Seed001(st) = &cfg.law {
        // validated in TractionModel::new: the oil exists for this law
        let Some(oil) = cfg.oil.as_ref() else {
            return Traction::default();
        };
        let hz = state.hertz();
        let sign = cfg.sliding_sign(v);
        let (t, clamped) = model.contact_temperature(state.temperature_k);
        if clamped {
            w |= Warnings::TEMPERATURE_CLAMPED;
        }
        let l = hz.length_m;
        let inp = Seed001Inputs {
            normal_force: q,
            length: if l.is_finite() {
                l
            } else {
                2.0 * hz.half_width_m
            },
            reduced_radius: state.reduced_radius_m,
            reduced_modulus: state.reduced_modulus_pa,
            half_width: hz.half_width_m,
            max_pressure: hz.max_pressure_pa,
            rolling_speed: u_abs,
            sliding_speed: v,
            ring_temperature: t,
            roughness: state.roughness_ra_m,
        };
        let r = seed001_friction(&inp, oil, st);
        if !r.converged {
            w |= Warnings::FLASH_NOT_CONVERGED;
        }
        if r.temperature_clamped {
            w |= Warnings::TEMPERATURE_CLAMPED;
        }
        let mu = r.f * sign;
        return Traction {
            coefficient: mu,
            hydrodynamic: r.f,
            boundary: r.f_asperity,
            regime: if r.asperity_fraction > 1e-3 {
                FrictionRegime::Mixed
            } else {
                FrictionRegime::Hydrodynamic
            },
            heat_power_w: mu.abs() * q * v.abs(),
            film_central_m: r.film,
            film_minimum_m: r.film,
            lambda: r.lambda,
            slip: s,
            mean_pressure_pa: hz.mean_pressure_pa,
            max_pressure_pa: hz.max_pressure_pa,
            half_width_m: hz.half_width_m,
            contact_temperature_k: r.contact_temperature_k,
            film_formula: Some(FilmFormula::Seed001),
            warnings: Warnings(w),
        };
    }

    let Some(prep) = model.prepare_contact(state, film) else {
        return Traction::default();
    };
    model.traction_prepared(&prep, state)
}

/// Where [`TractionModel::prepare_contact`] takes the film from.
#[derive(Debug, Clone, Copy)]
enum FilmSource {
    /// imposed by the caller as (h_c, h_min)
    Given((f64, f64)),
    /// the model's formula
    Formula,
    /// the model's formula, left to the batch when it is the rigid–piezoviscous line film
    DeferLineFormula,
}

/// The per-contact part of a lubricated traction evaluation: oil properties at the contact
/// temperature, the film and Λ (SPEC §4.3–4.4). One prepared contact serves every slice of a
/// roller–raceway line contact ([`TractionModel::traction_prepared`]); [`traction`] prepares
/// and evaluates a single state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PreparedContact {
    /// oil temperature of the contact (before clamping), K
    temperature_k: f64,
    props: HotProps,
    film_central_m: f64,
    film_minimum_m: f64,
    lambda: f64,
    /// `None` when the caller imposed the film
    formula: Option<FilmFormula>,
    warnings: u16,
}

impl PreparedContact {
    /// Central and minimum film, m.
    pub fn film(&self) -> (f64, f64) {
        (self.film_central_m, self.film_minimum_m)
    }
}

impl TractionModel {
    /// Oil temperature used for the properties (clamped into the oil's range when the model
    /// clamps) and whether it was clamped, K.
    fn contact_temperature(&self, t_in: f64) -> (f64, bool) {
        match self.cfg.oil.as_ref() {
            Some(oil) if self.cfg.clamp_temperature => {
                let tc = oil.clamp_temperature(t_in);
                (tc, tc != t_in)
            }
            _ => (t_in, false),
        }
    }

    /// Prepares the contact `whole` (its total load, length, entrainment speed and temperature):
    /// oil properties, film (`film` given as `(h_c, h_min)` or from the model's formula) and Λ.
    /// `None` for laws without a film (two-level, seed 001) or an unloaded contact.
    pub fn prepare_contact(
        &self,
        whole: &ContactState,
        film: Option<(f64, f64)>,
    ) -> Option<PreparedContact> {
        let source = match film {
            Some(given) => FilmSource::Given(given),
            None => FilmSource::Formula,
        };
        self.prepare(whole, source).map(|(prepared, _)| prepared)
    }

    /// [`TractionModel::prepare_contact`] with the model's formula, for [`SliceBatch`]: when
    /// the formula is the rigid–piezoviscous line film, the film and Λ are left NaN and `true`
    /// is returned, so that the batch computes the films of all its contacts in one vectorised
    /// loop ([`crate::film::rigid_piezoviscous_line_many`]) and completes them with
    /// [`TractionModel::set_film`].
    pub(crate) fn prepare_contact_deferred(
        &self,
        whole: &ContactState,
    ) -> Option<(PreparedContact, bool)> {
        self.prepare(whole, FilmSource::DeferLineFormula)
    }

    /// See [`TractionModel::prepare_contact`]; returns whether the film was deferred.
    fn prepare(&self, whole: &ContactState, source: FilmSource) -> Option<(PreparedContact, bool)> {
        let (props, formula, mut w) = self.prepare_oil(whole)?;
        let film = match source {
            FilmSource::Given(given) => Some(given),
            FilmSource::DeferLineFormula
                if matches!(
                    formula,
                    FilmFormula::RigidPiezoviscousLine | FilmFormula::Auto
                ) =>
            {
                None
            }
            _ => {
                let (film, pve) = self.formula_film(formula, &props, whole);
                if pve == Some(false) {
                    w |= Warnings::PVE_CONDITION_FAILED;
                }
                Some(film)
            }
        };
        let mut prepared = PreparedContact {
            temperature_k: whole.temperature_k,
            props,
            film_central_m: f64::NAN,
            film_minimum_m: f64::NAN,
            lambda: f64::NAN,
            formula: (!matches!(source, FilmSource::Given(_))).then_some(formula),
            warnings: w,
        };
        if let Some((hc, hm)) = film {
            self.set_film(&mut prepared, hc, hm, whole.roughness_ra_m);
        }
        Some((prepared, film.is_none()))
    }

    /// Oil properties at the (clamped) contact temperature, the film formula resolved for the
    /// contact's geometry, and the warnings so far. `None` for laws without a film or an
    /// unloaded contact.
    fn prepare_oil(&self, whole: &ContactState) -> Option<(HotProps, FilmFormula, u16)> {
        let cfg = &self.cfg;
        let FrictionLaw::Lubricated(_) = &cfg.law else {
            return None;
        };
        let oil = cfg.oil.as_ref()?;
        if whole.normal_force_n <= 0.0 {
            return None;
        }
        let mut w = 0u16;
        let (t, clamped) = self.contact_temperature(whole.temperature_k);
        if clamped {
            w |= Warnings::TEMPERATURE_CLAMPED;
        }
        let props = self
            .table
            .as_ref()
            .and_then(|tb| tb.get(t))
            .unwrap_or_else(|| HotProps::closed_form(oil, t));
        let (formula, mismatch) = resolve_formula(self.cfg.film.formula, whole.geometry.is_line());
        if mismatch {
            w |= Warnings::FILM_FORMULA_MISMATCH;
        }
        Some((props, formula, w))
    }

    /// Central and minimum film of `whole` by `formula` with the starvation factor, m, and the
    /// piezoviscous–elastic condition (point contacts).
    fn formula_film(
        &self,
        formula: FilmFormula,
        props: &HotProps,
        whole: &ContactState,
    ) -> ((f64, f64), Option<bool>) {
        let inp = FilmInputs {
            eta0: props.eta0,
            alpha: props.alpha,
            beta0: props.beta0,
            k_f: props.k_f,
            u: whole.rolling_speed_m_s.abs(),
            q: whole.normal_force_n,
            e: whole.reduced_modulus_pa,
            r: whole.reduced_radius_m,
        };
        let (hc, hm, pve, _) = film_core(formula, &inp, &whole.hertz(), self.cfg.film.seed001);
        let f = self.cfg.film.starvation_factor;
        ((hc * f, hm * f), pve)
    }

    /// Sets the film of `prepared`: `hc`, `hm` (m, starvation included) and Λ from `hm` and the
    /// roughness.
    pub(crate) fn set_film(&self, prepared: &mut PreparedContact, hc: f64, hm: f64, ra: [f64; 2]) {
        prepared.film_central_m = hc;
        prepared.film_minimum_m = hm;
        prepared.lambda = self.lambda_def.eval(hm, ra);
    }

    /// Traction of `state` (a slice of the prepared contact, or the whole of it) with the
    /// prepared oil properties, film and Λ: Muraki or constant hydrodynamic friction at the
    /// state's own Hertz pressure, half-width and sliding speed, blended with the boundary law
    /// by Λ (SPEC §4.5–4.7). The state's temperature is not re-read.
    #[inline]
    pub fn traction_prepared(&self, prep: &PreparedContact, state: &ContactState) -> Traction {
        let cfg = &self.cfg;
        let q = state.normal_force_n;
        let v = state.sliding_speed_m_s;
        let u_abs = state.rolling_speed_m_s.abs();
        let u_min = cfg.min_rolling_speed_m_s;
        let mut w = prep.warnings;
        if u_abs < u_min {
            w |= Warnings::ROLLING_SPEED_FLOORED;
        }
        let u_eff = u_abs.max(u_min);
        let s = v / u_eff;
        if q <= 0.0 {
            return Traction::unloaded(s, state.temperature_k, w);
        }
        let (FrictionLaw::Lubricated(lf), Some(oil)) = (&cfg.law, cfg.oil.as_ref()) else {
            return Traction::default();
        };
        let sign = cfg.sliding_sign(v);
        let (hz, pressure, inv_rolling_speed) = state.hertz_and_pressure(u_eff);
        let (hc, hm, lambda) = (prep.film_central_m, prep.film_minimum_m, prep.lambda);
        let LubricatedParts {
            mu_hd,
            mu_bd,
            mu,
            regime,
            warnings,
        } = lubricated_coefficient(
            lf,
            oil,
            &ContactTraction::new(lf, &prep.props, hc, lambda),
            &MurakiSlice {
                pressure,
                rolling_speed: u_eff,
                inv_rolling_speed,
                sliding_speed: v.abs(),
            },
        );
        w |= warnings;
        let coefficient = mu * sign;
        Traction {
            coefficient,
            hydrodynamic: mu_hd,
            boundary: mu_bd,
            regime,
            heat_power_w: coefficient.abs() * q * v.abs(),
            film_central_m: hc,
            film_minimum_m: hm,
            lambda,
            slip: s,
            mean_pressure_pa: hz.mean_pressure_pa,
            max_pressure_pa: hz.max_pressure_pa,
            half_width_m: hz.half_width_m,
            contact_temperature_k: prep.temperature_k,
            film_formula: prep.formula,
            warnings: Warnings(w),
        }
    }
}

/// The per-contact inputs of [`lubricated_coefficient`]: the contact's part of Muraki's law,
/// its Λ and the blend weight of (1.3) at that Λ (0 without a blend).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct ContactTraction {
    pub muraki: MurakiContact,
    pub lambda: f64,
    pub mixed_weight: f64,
}

impl ContactTraction {
    /// With the oil properties `pr` at the contact temperature, the central film `film_central`
    /// and the film parameter `lambda` of the contact.
    #[inline(always)]
    pub fn new(lf: &LubricatedFriction, pr: &HotProps, film_central: f64, lambda: f64) -> Self {
        Self {
            muraki: MurakiContact::new(
                pr.eta0,
                pr.alpha,
                pr.gamma,
                pr.tau0,
                pr.beta0,
                pr.k_f,
                film_central,
            ),
            lambda,
            mixed_weight: lf.mixed.map_or(0.0, |lim| lim.weight(lambda)),
        }
    }
}

/// μ_hd (Muraki or constant), μ_bd and the Λ blend (1.3) of a lubricated slice of `contact`
/// with its own mean pressure, half-width, rolling speed (already floored) and sliding speed
/// (SPEC §4.5–4.7). The one implementation behind [`TractionModel::traction_prepared`] and
/// [`SliceBatch::evaluate`]; call-free so that a loop over slices is vectorised.
#[inline(always)]
pub(crate) fn lubricated_coefficient(
    lf: &LubricatedFriction,
    oil: &Lubricant,
    contact: &ContactTraction,
    slice: &MurakiSlice,
) -> LubricatedParts {
    let mut warnings = 0u16;
    let mu_hd = match &lf.hydrodynamic {
        Hydrodynamic::Constant(m) => *m,
        Hydrodynamic::Muraki(ms) => {
            let out = muraki_slice(
                &contact.muraki,
                slice,
                oil.kappa_per_k_pa.unwrap_or(0.0),
                oil.roelands_z,
                ms,
            );
            if out.sqrt_negative {
                warnings |= Warnings::SQRT_NEGATIVE_F34;
            }
            if out.sigma_invalid {
                warnings |= Warnings::SIGMA_INVALID_F34;
            }
            out.mu
        }
    };
    let lambda = contact.lambda;
    let (mu, mu_bd, regime) = match &lf.mixed {
        None => (mu_hd, f64::NAN, FrictionRegime::Hydrodynamic),
        // μ_bd only matters below Λ_hd (mixed and boundary regimes)
        Some(lim) if lambda < lim.lambda_hd => {
            let mu_bd = lf
                .boundary
                .eval(slice.sliding_speed * slice.inv_rolling_speed);
            let (m, r) = mixed_friction_weighted(mu_bd, mu_hd, lambda, contact.mixed_weight, lim);
            (m, mu_bd, r)
        }
        Some(_) => (mu_hd, f64::NAN, FrictionRegime::Hydrodynamic),
    };
    LubricatedParts {
        mu_hd,
        mu_bd,
        mu,
        regime,
        warnings,
    }
}

/// Result of [`lubricated_coefficient`].
pub(crate) struct LubricatedParts {
    pub mu_hd: f64,
    pub mu_bd: f64,
    /// blended coefficient (magnitude)
    pub mu: f64,
    pub regime: FrictionRegime,
    pub warnings: u16,
}
