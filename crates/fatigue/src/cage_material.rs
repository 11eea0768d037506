//! The S–N curve a fatigue run uses (theory §10.5): the cage material's own curve and ultimate
//! strength (`cage.material`), knocked down by the coating factor of its plating
//! (`cage.plating`) and the stress safety factor. A run may replace the base curve (a CSV file)
//! or the plating's coating factor; a cage without S–N data, or a coating factor on an unplated
//! cage, is an error naming the model key.

use crate::damage::MeanStressSettings;
use crate::mean_stress::MeanStressCorrection;
use crate::sn::{BelowKnee, SnCurve, SnSettings};
use rolldyn_geometry::{CylindricalRollerBearing, FatigueStrength, Plating};
use serde::{Deserialize, Serialize};

/// Seed 000 §3.1.1.8: silver plating lowers the S–N curve by lg 1.5, i.e. divides its
/// amplitudes by 1.5.
pub const SILVER_COATING_FACTOR: f64 = 1.5;

/// The coating factor k_coat of a plating and its source.
pub fn plating_coating_factor(plating: Plating) -> (f64, &'static str) {
    match plating {
        Plating::Silver => (
            SILVER_COATING_FACTOR,
            "cage.plating = \"silver\" (seed 000 §3.1.1.8: lg 1.5)",
        ),
    }
}

/// What the fatigue evaluation needs of the cage's material; written into the load export so
/// that a run from an export uses the material of the model the loads came from.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CageMaterial {
    /// the name of `cage.material`
    pub name: String,
    /// its S–N curve and ultimate strength, if it has them
    pub fatigue: Option<FatigueStrength>,
    /// `cage.plating`
    pub plating: Option<Plating>,
}

impl CageMaterial {
    /// The material and plating of `bearing`'s cage (`None` without a cage).
    pub fn of(bearing: &CylindricalRollerBearing) -> Option<Self> {
        bearing.cage.as_ref().map(|cage| Self {
            name: cage.material.name.clone(),
            fatigue: cage.material.fatigue.clone(),
            plating: cage.plating,
        })
    }
}

/// What a run asks of the S–N curve besides the cage material's data.
#[derive(Debug, Clone, PartialEq)]
pub struct SnChoice {
    /// a base curve replacing the material's, with its source (`--sn-curve FILE`)
    pub curve: Option<(SnCurve, String)>,
    /// a coating factor replacing the plating's (`--coating-factor`); an error on an unplated cage
    pub coating_factor: Option<f64>,
    /// k_safety, dividing the curve besides the coating factor
    pub stress_safety_factor: f64,
    pub below_knee: BelowKnee,
}

impl Default for SnChoice {
    fn default() -> Self {
        Self {
            curve: None,
            coating_factor: None,
            stress_safety_factor: 1.0,
            below_knee: BelowKnee::NoDamage,
        }
    }
}

/// The S–N curve a run used and where each part of it came from (`rolldyn fatigue --json`,
/// key `sn`).
#[derive(Debug, Clone, Serialize)]
pub struct SnUsed {
    /// `cage.material`
    pub material: String,
    /// where the base curve comes from
    pub curve_source: String,
    /// σ_u of the Goodman and Gerber corrections, Pa (null when not known and not needed)
    pub ultimate_strength_pa: Option<f64>,
    pub coating_factor: f64,
    /// where the coating factor comes from
    pub coating_source: String,
    pub stress_safety_factor: f64,
    /// the allowable curve: the base curve with the knock-downs and the knee treatment
    #[serde(skip)]
    pub curve: SnCurve,
    /// the mean-stress correction with its σ_u
    #[serde(skip)]
    pub mean_stress: MeanStressSettings,
}

/// The S–N curve of a run on a cage of `material` (`None`: an export that names none) with the
/// run's `choice` and mean-stress `correction`.
pub fn resolve(
    material: Option<&CageMaterial>,
    choice: &SnChoice,
    correction: MeanStressCorrection,
) -> Result<SnUsed, String> {
    let material = material.ok_or(
        "the load export names no cage material (written by an older rolldyn): export the loads again (simulate --cage-loads)",
    )?;
    let name = &material.name;
    let (base, curve_source) = match (&choice.curve, &material.fatigue) {
        (Some((curve, source)), _) => (curve.clone(), source.clone()),
        (None, Some(strength)) => (
            SnCurve::of_material(strength)
                .map_err(|e| format!("materials.{name}.sn_curve: {e}"))?,
            strength.source.clone(),
        ),
        (None, None) => {
            return Err(format!(
                "cage.material = \"{name}\" has no S–N curve: give [materials.{name}] an sn_curve with ultimate_strength (or fatigue_like = \"<built-in material>\"), or give --sn-curve FILE"
            ));
        }
    };
    let (coating_factor, coating_source) = match (material.plating, choice.coating_factor) {
        (Some(plating), None) => {
            let (k, source) = plating_coating_factor(plating);
            (k, source.to_string())
        }
        (Some(plating), Some(k)) => {
            let (own, _) = plating_coating_factor(plating);
            (
                k,
                format!("coating_factor (--coating-factor), replacing the plating's {own}"),
            )
        }
        (None, Some(k)) => {
            return Err(format!(
                "coating_factor (--coating-factor) {k} on an unplated cage: the model gives no cage.plating (e.g. plating = \"silver\" in [cage])"
            ));
        }
        (None, None) => (1.0, "unplated (no cage.plating)".to_string()),
    };
    let ultimate = material.fatigue.as_ref().map(|f| f.ultimate_strength);
    let needs_ultimate = matches!(
        correction,
        MeanStressCorrection::Goodman | MeanStressCorrection::Gerber
    );
    if needs_ultimate && ultimate.is_none() {
        return Err(format!(
            "--mean-stress {correction:?} needs the ultimate strength of cage.material = \"{name}\": give [materials.{name}] ultimate_strength with its sn_curve"
        ));
    }
    let curve = base
        .with_settings(SnSettings {
            coating_factor,
            stress_safety_factor: choice.stress_safety_factor,
            below_knee: choice.below_knee,
        })
        .map_err(|e| format!("--coating-factor/--safety-factor: {e}"))?;
    Ok(SnUsed {
        material: name.clone(),
        curve_source,
        ultimate_strength_pa: ultimate,
        coating_factor,
        coating_source,
        stress_safety_factor: choice.stress_safety_factor,
        curve,
        mean_stress: MeanStressSettings {
            correction,
            // σ_u enters only Goodman and Gerber, which require it above
            ultimate_strength_pa: ultimate.unwrap_or(f64::NAN),
        },
    })
}
