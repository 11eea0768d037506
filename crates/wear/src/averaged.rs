//! The averaged-parameter method: equivalent force and mean sliding speed over the time a
//! contact carries load in one cage revolution (seed 000 §2.4.2, eqs. 2.35–2.37; flags F-46,
//! F-49; docs/theory.md §8.3).

/// Exponent of the seed's equivalent force (2.36): pressure ∝ Q^(1/3), Hertz point contact. For a
/// Hertz line contact the exponent would be 1/2 (flag F-49).
pub const SEED_EQUIVALENT_FORCE_EXPONENT: f64 = 1.0 / 3.0;

/// Running sums of the averaged-parameter method over the intervals with Q > 0 (seed 000 eqs.
/// 2.36, 2.37; exponent configurable, default 1/3, flag F-49).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AveragedContact {
    /// Σ τᵢ, s
    contact_time_s: f64,
    /// Σ Qᵢᵉ τᵢ, Nᵉ·s
    force_power_time: f64,
    /// Σ |vᵢ| τᵢ, m
    sliding_distance_m: f64,
    /// e of (2.36)
    exponent: f64,
}

impl AveragedContact {
    /// Empty sums with the equivalent-force exponent `exponent`.
    ///
    /// # Panics
    /// When `exponent` is not positive and finite.
    pub fn new(exponent: f64) -> Self {
        assert!(
            exponent.is_finite() && exponent > 0.0,
            "equivalent-force exponent {exponent} must be positive and finite"
        );
        Self {
            contact_time_s: 0.0,
            force_power_time: 0.0,
            sliding_distance_m: 0.0,
            exponent,
        }
    }

    /// Adds an interval of `duration_s` with normal force `force_n` and sliding speed
    /// `sliding_speed_m_s` (its magnitude counts); intervals with Q ≤ 0 carry no load and are
    /// ignored (seed 000 §2.4.2).
    pub fn add(&mut self, force_n: f64, sliding_speed_m_s: f64, duration_s: f64) {
        if force_n > 0.0 {
            self.contact_time_s += duration_s;
            self.force_power_time += force_n.powf(self.exponent) * duration_s;
            self.sliding_distance_m += sliding_speed_m_s.abs() * duration_s;
        }
    }

    /// Equivalent force Q_e = (Σ Qᵉ τ / Σ τ)^(1/e), N (seed 000 eq. 2.36); 0 when no contact.
    pub fn equivalent_force(&self) -> f64 {
        self.mean_over_contact(self.force_power_time)
            .powf(1.0 / self.exponent)
    }

    /// Mean sliding speed v̄ = Σ |v| τ / Σ τ, m/s (seed 000 eq. 2.37); 0 when no contact.
    pub fn mean_sliding_speed(&self) -> f64 {
        self.mean_over_contact(self.sliding_distance_m)
    }

    /// Σ τ, the time the contact carries load, s.
    pub fn contact_time(&self) -> f64 {
        self.contact_time_s
    }

    /// The equivalent-force exponent e.
    pub fn exponent(&self) -> f64 {
        self.exponent
    }

    /// Adds the sums of `other`, as if its intervals had been added here.
    ///
    /// # Panics
    /// When the two exponents differ.
    pub fn merge(&mut self, other: &Self) {
        assert_eq!(
            self.exponent, other.exponent,
            "averaged contacts with different equivalent-force exponents"
        );
        self.contact_time_s += other.contact_time_s;
        self.force_power_time += other.force_power_time;
        self.sliding_distance_m += other.sliding_distance_m;
    }

    fn mean_over_contact(&self, sum: f64) -> f64 {
        if self.contact_time_s > 0.0 {
            sum / self.contact_time_s
        } else {
            0.0
        }
    }
}

impl Default for AveragedContact {
    /// The seed's exponent 1/3.
    fn default() -> Self {
        Self::new(SEED_EQUIVALENT_FORCE_EXPONENT)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::coefficient::WearCoefficient;
    use crate::law::archard_rate;
    use approx::assert_relative_eq;

    fn sums(exponent: f64, intervals: &[(f64, f64, f64)]) -> AveragedContact {
        let mut contact = AveragedContact::new(exponent);
        for &(force, speed, duration) in intervals {
            contact.add(force, speed, duration);
        }
        contact
    }

    const VARYING: [(f64, f64, f64); 4] = [
        (1.0, 2.0, 1e-4),
        (8.0, -4.0, 1e-4),
        (0.5, 1.0, 2e-4),
        (3.0, 6.0, 5e-5),
    ];

    #[test]
    fn constant_force_is_its_own_equivalent_force() {
        for exponent in [SEED_EQUIVALENT_FORCE_EXPONENT, 0.5, 1.0] {
            let contact = sums(exponent, &[(2.25, 40.0, 1e-5), (2.25, 40.0, 3e-5)]);
            assert_relative_eq!(contact.equivalent_force(), 2.25, max_relative = 1e-12);
            assert_relative_eq!(contact.mean_sliding_speed(), 40.0, max_relative = 1e-12);
            assert_relative_eq!(contact.contact_time(), 4e-5, max_relative = 1e-12);
        }
    }

    #[test]
    fn equivalent_force_by_hand_and_exponent_ordering() {
        // (2.36): 1 N and 8 N for equal times: ((1 + 2)/2)³ = 3.375 N
        let two = sums(1.0 / 3.0, &[(1.0, 0.0, 1.0), (8.0, 0.0, 1.0)]);
        assert_relative_eq!(two.equivalent_force(), 3.375, max_relative = 1e-12);
        // power means grow with the exponent: Q_e(1/3) < Q_e(1/2) < time-mean force
        let third = sums(SEED_EQUIVALENT_FORCE_EXPONENT, &VARYING).equivalent_force();
        let half = sums(0.5, &VARYING).equivalent_force();
        let mean = sums(1.0, &VARYING).equivalent_force();
        let total: f64 = VARYING.iter().map(|i| i.2).sum();
        let by_hand: f64 = VARYING.iter().map(|i| i.0 * i.2).sum::<f64>() / total;
        assert_relative_eq!(mean, by_hand, max_relative = 1e-12);
        assert!(third < half && half < mean, "{third} {half} {mean}");
    }

    #[test]
    fn intervals_without_load_are_ignored() {
        let mut with_gaps = sums(SEED_EQUIVALENT_FORCE_EXPONENT, &VARYING);
        with_gaps.add(0.0, 80.0, 1e-3);
        with_gaps.add(-2.0, 80.0, 1e-3);
        assert_eq!(with_gaps, sums(SEED_EQUIVALENT_FORCE_EXPONENT, &VARYING));
        // (2.37) with |v|: (2 + 4 + 2 + 3) · 1e-4 s·m/s / 4.5e-4 s
        assert_relative_eq!(
            with_gaps.mean_sliding_speed(),
            11.0 / 4.5,
            max_relative = 1e-12
        );
        let empty = sums(SEED_EQUIVALENT_FORCE_EXPONENT, &[(0.0, 10.0, 1.0)]);
        assert_eq!(empty.equivalent_force(), 0.0);
        assert_eq!(empty.mean_sliding_speed(), 0.0);
        assert_eq!(empty.contact_time(), 0.0);
    }

    #[test]
    fn merge_equals_sequential_adds() {
        let mut first = sums(0.5, &VARYING[..2]);
        first.merge(&sums(0.5, &VARYING[2..]));
        let all = sums(0.5, &VARYING);
        assert_relative_eq!(
            first.equivalent_force(),
            all.equivalent_force(),
            max_relative = 1e-14
        );
        assert_relative_eq!(
            first.mean_sliding_speed(),
            all.mean_sliding_speed(),
            max_relative = 1e-14
        );
        assert_relative_eq!(
            first.contact_time(),
            all.contact_time(),
            max_relative = 1e-14
        );
    }

    /// Seed 000 Table 3.5 (1032930 engine start-up, wear line through the pressure maximum):
    /// time s, mean pressure roller Pa, mean pressure inner ring Pa, sliding speed m/s, Λ
    /// (Ra raceway 0.2 µm, roller 0.16 µm). The friction coefficient and temperature columns
    /// do not enter (2.35).
    const SEED_TABLE_3_5: [(f64, f64, f64, f64, f64); 8] = [
        (82.1, 1.004e8, 6.663e7, 1.12, 3.0),
        (85.3, 1.450e8, 6.618e7, 29.6, 2.9),
        (101.9, 1.663e8, 8.299e7, 25.7, 2.9),
        (109.5, 2.192e8, 1.198e8, 11.56, 3.0),
        (144.3, 2.525e8, 1.377e8, 11.38, 2.9),
        (160.3, 2.598e8, 1.188e8, 18.14, 2.8),
        (184.3, 2.915e8, 1.459e8, 9.7, 2.5),
        (270.5, 1.195e8, 1.246e8, 2.85, 2.1),
    ];

    #[test]
    fn v22_start_up_wear_rates_of_table_3_5_have_the_shape_of_fig_3_73() {
        // H: examples/1032930.toml gives its rings and rollers no material, so they are the
        // workspace's bearing steel (Meyer 7.6 GPa ≈ 62 HRC); k(Λ) the default table.
        let hardness = rolldyn_geometry::Material::bearing_steel()
            .meyer_hardness
            .unwrap();
        let k_of = WearCoefficient::seed_default();
        println!(
            "time s | p roller Pa | p ring Pa | v m/s | Λ | k | rate roller m/s | rate ring m/s"
        );
        let rates: Vec<f64> = SEED_TABLE_3_5
            .iter()
            .map(|&(time, p_roller, p_ring, v, lambda)| {
                let k = k_of.film(lambda);
                let roller = archard_rate(k, p_roller, v, hardness);
                let ring = archard_rate(k, p_ring, v, hardness);
                println!(
                    "{time} | {p_roller:.4e} | {p_ring:.4e} | {v} | {lambda} | {k:.4e} | \
                     {roller:.3e} | {ring:.3e}"
                );
                ring
            })
            .collect();
        // sharp rise just after the starter cut-off (82.1 → 85.3 s): sliding 1.12 → 29.6 m/s
        assert!(rates[1] > 20.0 * rates[0], "{rates:?}");
        // a marked decrease at steady state (270.5 s): the lowest rate after the cut-off
        let last = rates[7];
        assert!(last < 0.5 * rates[6], "{rates:?}");
        assert!(rates[1..7].iter().all(|&r| r > 2.0 * last), "{rates:?}");
        // the maximum lies between cut-off and steady state (160.3 s with these inputs)
        let peak = rates.iter().cloned().fold(0.0, f64::max);
        assert_eq!(peak, rates[5]);
        // by hand, 85.3 s: k = 4.55e-11 (2.5/2.9)² = 3.3814e-11; 3.3814e-11 · 6.618e7 · 29.6 / 7.6e9
        assert_relative_eq!(rates[1], 8.716e-12, max_relative = 1e-3);
    }
}
