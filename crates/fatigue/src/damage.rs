//! Linear damage accumulation (Palmgren–Miner; theory §10.5, seed 000 §2.5): the counted cycles
//! of one repeat of a stress history (one steady cage revolution) each do d_j = n_j / N_j, with
//! N_j read on the allowable S–N curve at the equivalent fully reversed amplitude; the damage
//! per repeat D = Σ d_j, the life L = 1/D repeats (∞ when D = 0), in hours L_h = L_rev/(60 n_c).
//!
//! Serialised results write an infinite N_j or life as JSON `null` (serde_json's rule for
//! non-finite numbers): "no damage".

use crate::mean_stress::MeanStressCorrection;
use crate::rainflow::Cycle;
use crate::sn::{AISI_4340_ULTIMATE_STRENGTH_PA, SnCurve};
use serde::{Deserialize, Serialize};
use std::f64::consts::TAU;

/// Seconds in an hour.
const HOUR_S: f64 = 3600.0;

/// How a cycle's mean stress enters the damage.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct MeanStressSettings {
    pub correction: MeanStressCorrection,
    /// σ_u for Goodman and Gerber, Pa; default AISI 4340 (Dowling 2013, Table 9.1: 1172 MPa)
    pub ultimate_strength_pa: f64,
}

impl Default for MeanStressSettings {
    fn default() -> Self {
        Self {
            correction: MeanStressCorrection::default(),
            ultimate_strength_pa: AISI_4340_ULTIMATE_STRENGTH_PA,
        }
    }
}

/// The damage one counted cycle does.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct CycleDamage {
    /// amplitude σ_a = range/2, Pa
    pub amplitude_pa: f64,
    /// mean σ_m, Pa
    pub mean_pa: f64,
    /// equivalent fully reversed amplitude σ_ar, Pa
    pub equivalent_amplitude_pa: f64,
    /// n_j: 1 for a full cycle, ½ for a half cycle
    pub count: f64,
    /// N_j on the allowable curve (∞: no damage)
    pub cycles_to_failure: f64,
    /// d_j = n_j / N_j
    pub damage: f64,
}

/// Miner's sum over the cycles of one repeat of a history, with each cycle's share.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DamageBreakdown {
    /// one entry per counted cycle, in the order of counting
    pub cycles: Vec<CycleDamage>,
    /// D = Σ d_j per repeat of the history
    pub damage_per_repeat: f64,
    /// L = 1/D repeats (∞ when D = 0)
    pub life_repeats: f64,
}

impl DamageBreakdown {
    /// The `count` cycles of largest damage, largest first.
    pub fn largest(&self, count: usize) -> Vec<CycleDamage> {
        let mut sorted = self.cycles.clone();
        sorted.sort_by(|a, b| b.damage.total_cmp(&a.damage));
        sorted.truncate(count);
        sorted
    }
}

/// Miner's damage of the counted `cycles` (stresses in Pa) of one repeat of a history on `curve`
/// (linear Miner rule, seed 000 §2.5 step 6).
pub fn miner_damage(
    cycles: &[Cycle],
    curve: &SnCurve,
    mean_stress: &MeanStressSettings,
) -> DamageBreakdown {
    let cycles: Vec<CycleDamage> = cycles
        .iter()
        .map(|c| {
            let amplitude = 0.5 * c.range;
            let equivalent = mean_stress.correction.equivalent_amplitude(
                amplitude,
                c.mean,
                mean_stress.ultimate_strength_pa,
            );
            let cycles_to_failure = curve.cycles_to_failure(equivalent);
            CycleDamage {
                amplitude_pa: amplitude,
                mean_pa: c.mean,
                equivalent_amplitude_pa: equivalent,
                count: c.count,
                cycles_to_failure,
                damage: c.count / cycles_to_failure,
            }
        })
        .collect();
    let damage_per_repeat: f64 = cycles.iter().map(|c| c.damage).sum();
    DamageBreakdown {
        cycles,
        damage_per_repeat,
        life_repeats: 1.0 / damage_per_repeat,
    }
}

/// Hours to run `revolutions` cage revolutions at `cage_speed_rad_s`: L_h = L_rev / (60 n_c) with
/// n_c in rpm (SPEC §7.5), i.e. 2π L_rev / (|ω_c| · 3600 s); the sense of rotation does not matter.
pub fn life_hours(revolutions: f64, cage_speed_rad_s: f64) -> f64 {
    TAU * revolutions / (cage_speed_rad_s.abs() * HOUR_S)
}
