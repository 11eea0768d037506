//! Friction laws of the contacts, built once per operating point from the conditions:
//! the raceway traction model of the lubrication crate (seed 001 or seed 000 / Muraki, SPEC
//! §4.4–4.9) and the roller ↔ cage-bar law.

use crate::conditions::{BarFriction, FrictionModel, QuasiStaticConditions};
use crate::error::QsError;
use rolldyn_lubrication::traction::{
    FrictionLaw, Hydrodynamic, LubricatedFriction, TractionConfig, regularisation,
};
use rolldyn_lubrication::{
    BoundaryFriction, ContactState, FilmFormula, FilmSettings, LambdaDefinition, MixedLimits,
    Traction, TractionModel, traction,
};

/// Regularisation half-width of the constant bar friction around zero sliding, m/s.
pub const BAR_REGULARISATION_M_S: f64 = 1e-3;

/// Friction law of the roller ↔ cage-bar contact.
#[derive(Debug, Clone, PartialEq)]
pub enum BarLaw {
    /// A traction model (line contact roller ↔ flat bar).
    Traction(Box<TractionModel>),
    /// Constant coefficient, odd in the sliding speed (smoothed over ±1 mm/s).
    Constant(f64),
}

impl BarLaw {
    /// Signed friction coefficient (sign of the sliding speed of `state`) and the traction
    /// details when a traction model is used.
    pub fn eval(&self, state: &ContactState) -> (f64, Option<Traction>) {
        match self {
            BarLaw::Traction(m) => {
                let t = traction(state, m);
                (t.coefficient, Some(t))
            }
            BarLaw::Constant(mu) => (
                mu * regularisation(state.sliding_speed_m_s, BAR_REGULARISATION_M_S),
                None,
            ),
        }
    }
}

/// Builds the raceway traction model of `cond`.
pub fn raceway_model(cond: &QuasiStaticConditions) -> Result<TractionModel, QsError> {
    let oil = cond.lubricant.clone();
    let cfg = match &cond.friction {
        FrictionModel::Seed001(st) => TractionConfig {
            oil: Some(oil),
            law: FrictionLaw::Seed001(*st),
            film: FilmSettings {
                formula: FilmFormula::Seed001,
                ..FilmSettings::default()
            },
            lambda_definition: Some(LambdaDefinition::Tallian),
            ..TractionConfig::default()
        },
        FrictionModel::Muraki {
            settings,
            mixed,
            film,
        } => {
            let mixed = mixed.or_else(|| {
                oil.mixed_friction.map(|d| MixedLimits {
                    lambda_bd: d.lambda_bd,
                    lambda_hd: d.lambda_hd,
                })
            });
            TractionConfig {
                oil: Some(oil),
                law: FrictionLaw::Lubricated(LubricatedFriction {
                    hydrodynamic: Hydrodynamic::Muraki(*settings),
                    boundary: BoundaryFriction::Kragelsky,
                    mixed,
                }),
                film: FilmSettings {
                    formula: *film,
                    ..FilmSettings::default()
                },
                lambda_definition: Some(LambdaDefinition::Seed000),
                ..TractionConfig::default()
            }
        }
        FrictionModel::Custom(cfg) => TractionConfig {
            oil: Some(oil),
            ..(**cfg).clone()
        },
    };
    TractionModel::new(cfg).map_err(|e| QsError::Lubrication(e.to_string()))
}

/// Builds the bar law of `cond` (see [`BarFriction`]).
pub fn bar_law(cond: &QuasiStaticConditions, raceway: &TractionModel) -> Result<BarLaw, QsError> {
    let same = || BarLaw::Traction(Box::new(raceway.clone()));
    Ok(match cond.bar_friction {
        BarFriction::SameAsRaceways => same(),
        BarFriction::Constant(mu) => {
            if !(mu.is_finite() && mu >= 0.0) {
                return Err(QsError::InvalidInput(format!(
                    "bar friction coefficient must be ≥ 0, got {mu}"
                )));
            }
            BarLaw::Constant(mu)
        }
        BarFriction::Auto => match cond.friction {
            FrictionModel::Seed001(_) => same(),
            _ => BarLaw::Constant(0.01),
        },
    })
}
