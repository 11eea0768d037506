//! Duty cycles: the lives of several operating conditions combined by the Palmgren–Miner rule
//! (ISO 281:2007 §9.5 refers to it for variable operating conditions).

/// One condition of a duty cycle: its share of the operating time, the speed and the life the
/// bearing would have if it ran in this condition only.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DutyCondition {
    /// Share of the time (any positive weights; normalised by their sum).
    pub time_weight: f64,
    /// Speed of the rotating ring relative to the other [rad/s].
    pub speed_rad_s: f64,
    /// Life in this condition alone [revolutions].
    pub life_revolutions: f64,
}

/// A combined life.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct DutyLife {
    pub revolutions: f64,
    pub hours: f64,
}

/// Palmgren–Miner: each condition i consumes the fraction u_i/L_i of the life, u_i its share of
/// the revolutions (t_i n_i / Σ t_j n_j), so L = 1 / Σ_i (u_i / L_i) revolutions; in hours
/// L_h = L / (Σ t_i n_i) with the time shares normalised. `None` for an empty cycle or one
/// without revolutions.
pub fn palmgren_miner(conditions: &[DutyCondition]) -> Option<DutyLife> {
    let time: f64 = conditions.iter().map(|c| c.time_weight).sum();
    let revs_per_s: f64 = conditions
        .iter()
        .map(|c| c.time_weight / time * c.speed_rad_s.abs() / (2.0 * std::f64::consts::PI))
        .sum();
    if !(time > 0.0 && revs_per_s > 0.0) {
        return None;
    }
    let damage: f64 = conditions
        .iter()
        .map(|c| {
            let share = c.time_weight / time * c.speed_rad_s.abs()
                / (2.0 * std::f64::consts::PI)
                / revs_per_s;
            share / c.life_revolutions
        })
        .sum();
    let revolutions = 1.0 / damage;
    Some(DutyLife {
        revolutions,
        hours: revolutions / revs_per_s / 3600.0,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    /// Two conditions, half the time each at 1000 and 3000 r/min, lives 4e9 and 1e9
    /// revolutions: shares 1/4 and 3/4, L = 1/(0.25/4e9 + 0.75/1e9) = 1.2308e9 revolutions;
    /// mean 2000 r/min → 10 256 h.
    #[test]
    fn miner_by_hand() {
        let rpm = |n: f64| n * PI / 30.0;
        let life = palmgren_miner(&[
            DutyCondition {
                time_weight: 0.5,
                speed_rad_s: rpm(1000.0),
                life_revolutions: 4e9,
            },
            DutyCondition {
                time_weight: 0.5,
                speed_rad_s: rpm(3000.0),
                life_revolutions: 1e9,
            },
        ])
        .unwrap();
        assert!((life.revolutions / 1.230_769e9 - 1.0).abs() < 1e-6);
        assert!((life.hours - life.revolutions / (2000.0 * 60.0)).abs() < 1e-6);
        assert!(palmgren_miner(&[]).is_none());
    }

    #[test]
    fn one_condition_is_its_own_life() {
        let c = DutyCondition {
            time_weight: 3.0,
            speed_rad_s: 100.0,
            life_revolutions: 5e8,
        };
        let life = palmgren_miner(&[c]).unwrap();
        assert!((life.revolutions - 5e8).abs() < 1e-3);
        assert!(
            palmgren_miner(&[DutyCondition {
                life_revolutions: f64::INFINITY,
                ..c
            }])
            .unwrap()
            .revolutions
            .is_infinite()
        );
    }
}
